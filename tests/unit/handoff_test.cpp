// Ownership bookkeeping: handoffs are applied exactly once, by the service they are addressed to.
#include <gtest/gtest.h>

#include "traffic/fleet.hpp"
#include "traffic/handoff.hpp"

namespace entourage {
namespace {

constexpr ServiceId kGen{Role::kGenerator, 0};
constexpr ServiceId kMicro{Role::kMicro, 0};
constexpr ServiceId kMeso{Role::kMeso, 0};

Vehicle vehicle(VehicleId id, double s = 100.0, double v = 30.0) {
  Vehicle x;
  x.id = id;
  x.s_m = s;
  x.speed_mps = v;
  return x;
}

TEST(Handoff, MakeHandoffAdvancesTheSequence) {
  Vehicle v = vehicle(7);
  v.handoff_sequence = 3;
  const Handoff h = make_handoff(v, 10, kMicro, Role::kMeso, Region::kOuterRear, HandoffReason::kBorder);
  EXPECT_EQ(h.vehicle.handoff_sequence, 4U);
  EXPECT_EQ(h.step, 10U);
  EXPECT_EQ(h.from, kMicro);
}

TEST(Handoff, OnlyTheAddresseeAcceptsIt) {
  HandoffInbox micro(Role::kMicro, {Region::kInner});
  HandoffInbox meso_front(Role::kMeso, {Region::kOuterFront});
  HandoffInbox meso_rear(Role::kMeso, {Region::kOuterRear});
  const Handoff h = make_handoff(vehicle(1), 0, kGen, Role::kMeso, Region::kOuterFront, HandoffReason::kBirth);
  EXPECT_TRUE(micro.accept({h}).empty());
  EXPECT_TRUE(meso_rear.accept({h}).empty());
  EXPECT_EQ(meso_front.accept({h}).size(), 1U);
}

TEST(Handoff, DuplicatesAreDroppedAndCounted) {
  HandoffInbox micro(Role::kMicro, {Region::kInner});
  const Handoff h = make_handoff(vehicle(1), 5, kMeso, Role::kMicro, Region::kInner, HandoffReason::kBorder);
  EXPECT_EQ(micro.accept({h, h}).size(), 1U);  // a retransmission in the same batch
  EXPECT_EQ(micro.accept({h}).size(), 0U);     // and a late one
  EXPECT_EQ(micro.duplicates(), 2U);
}

TEST(Handoff, AVehicleComingBackIsAcceptedAgain) {
  HandoffInbox meso(Role::kMeso, {Region::kOuterRear, Region::kOuterFront});
  Vehicle v = vehicle(9);
  const Handoff birth = make_handoff(v, 0, kGen, Role::kMeso, Region::kOuterRear, HandoffReason::kBirth);
  ASSERT_EQ(meso.accept({birth}).size(), 1U);
  const Handoff to_micro = make_handoff(birth.vehicle, 10, kMeso, Role::kMicro, Region::kInner, HandoffReason::kBorder);
  meso.note_sent(to_micro);
  const Handoff back = make_handoff(to_micro.vehicle, 50, kMicro, Role::kMeso, Region::kOuterRear, HandoffReason::kBorder);
  EXPECT_EQ(back.vehicle.handoff_sequence, 3U);
  EXPECT_EQ(meso.accept({back}).size(), 1U);
  // the old birth arriving again after all that is not applied a second time
  EXPECT_TRUE(meso.accept({birth}).empty());
}

TEST(Handoff, ABirthFromTheDirectorIsAcceptedOnceWithItsControl) {
  constexpr ServiceId kDirector{Role::kDirector, 0};
  HandoffInbox meso(Role::kMeso, {Region::kOuterRear, Region::kOuterFront});
  Vehicle v = vehicle(kDirectorFirstVehicleId);
  v.control.mode = ControlMode::kTransported;
  v.control.play_id = 2;
  const Handoff birth = make_handoff(v, 30, kDirector, Role::kMeso, Region::kOuterFront, HandoffReason::kDirector);
  EXPECT_EQ(birth.vehicle.handoff_sequence, 1U);  // as the generator's births
  const auto out = meso.accept({birth, birth});
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].vehicle.control.mode, ControlMode::kTransported);
  EXPECT_EQ(out[0].vehicle.control.play_id, 2U);
  EXPECT_EQ(meso.duplicates(), 1U);
}

TEST(Handoff, AcceptedInDeterministicOrder) {
  HandoffInbox micro(Role::kMicro, {Region::kInner});
  const Handoff a = make_handoff(vehicle(5), 3, kMeso, Role::kMicro, Region::kInner, HandoffReason::kBorder);
  const Handoff b = make_handoff(vehicle(2), 3, kMeso, Role::kMicro, Region::kInner, HandoffReason::kBorder);
  const Handoff c = make_handoff(vehicle(9), 2, kGen, Role::kMicro, Region::kInner, HandoffReason::kInitialFill);
  const auto out = micro.accept({a, b, c});
  ASSERT_EQ(out.size(), 3U);
  EXPECT_EQ(out[0].vehicle.id, 9U);  // older step first
  EXPECT_EQ(out[1].vehicle.id, 2U);
  EXPECT_EQ(out[2].vehicle.id, 5U);
}

TEST(Fleet, AdoptKeepsIdOrderAndReplacesAnEarlierCopy) {
  Fleet f;
  f.adopt(make_handoff(vehicle(5), 0, kGen, Role::kMicro, Region::kInner, HandoffReason::kBirth), 0, 0.1);
  f.adopt(make_handoff(vehicle(2), 0, kGen, Role::kMicro, Region::kInner, HandoffReason::kBirth), 0, 0.1);
  f.adopt(make_handoff(vehicle(5, 200.0), 0, kGen, Role::kMicro, Region::kInner, HandoffReason::kBirth), 0, 0.1);
  ASSERT_EQ(f.size(), 2U);
  EXPECT_EQ(f.vehicles()[0].id, 2U);
  EXPECT_EQ(f.vehicles()[1].id, 5U);
  EXPECT_DOUBLE_EQ(f.vehicles()[1].s_m, 200.0);
  EXPECT_TRUE(f.owns(2));
  EXPECT_FALSE(f.owns(3));
}

TEST(Fleet, ALateHandoffIsBroughtForwardNotLost) {
  Fleet f;
  // state of step 10, applied when the service is at step 13 (real time, a late message)
  f.adopt(make_handoff(vehicle(1, 100.0, 20.0), 10, kMeso, Role::kMicro, Region::kInner, HandoffReason::kBorder), 13,
          0.1);
  EXPECT_NEAR(f.vehicles()[0].s_m, 100.0 + 3 * 0.1 * 20.0, 1e-9);
}

TEST(Fleet, ExtractRemovesAndReturnsInIdOrder) {
  Fleet f;
  for (VehicleId id : {4U, 1U, 3U, 2U}) {
    f.adopt(make_handoff(vehicle(id, id * 10.0), 0, kGen, Role::kMicro, Region::kInner, HandoffReason::kBirth), 0, 0.1);
  }
  const auto out = f.extract_if([](const Vehicle& v) { return v.s_m > 15.0; });
  ASSERT_EQ(out.size(), 3U);
  EXPECT_EQ(out[0].id, 2U);
  EXPECT_EQ(out[2].id, 4U);
  EXPECT_EQ(f.size(), 1U);
}

}  // namespace
}  // namespace entourage
