// Carrying a published vehicle state forward (traffic/carried_states.hpp): a reader that holds one
// state of a meso vehicle computes its later steps exactly as meso moves it, so meso need publish
// only the states a reader cannot carry forward.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <vector>

#include "core_test_util.hpp"
#include "dds/convert.hpp"
#include "road/road.hpp"
#include "traffic/carried_states.hpp"
#include "traffic/driving.hpp"
#include "window_cores.hpp"

namespace entourage {
namespace {

constexpr double kDt_s = 0.1;

Vehicle moving_vehicle() {
  Vehicle v;
  v.id = 7;
  v.direction = Direction::kBackward;
  v.lane = 0;
  v.s_m = 2000.0;
  v.speed_mps = 3.0;
  v.accel_mps2 = -1.3;  // stops within the run
  v.lane_change = {0, 1, LaneChangePhase::kMoving, 0.35, 1.2, 0.0, 0.0};  // finishes within the run
  return v;
}

// MesoCore::move for one vehicle.
void move_as_meso(Vehicle& v) {
  advance_on_ramp(v.s_m, v.speed_mps, v.accel_mps2, v.direction, kDt_s);
  continue_lane_change(v, kDt_s);
}

TEST(CarriedStates, AStateCarriedForwardIsTheVehicleMovedAsMesoMovesIt) {
  Vehicle v = moving_vehicle();
  VehicleReport carried(v, Region::kOuterFront);
  for (int k = 0; k < 40; ++k) {
    move_as_meso(v);
    carried = carried_forward(carried, kDt_s);
    ASSERT_TRUE(same_state(carried, VehicleReport(v, Region::kOuterFront))) << "step " << k;
  }
  EXPECT_EQ(v.speed_mps, 0.0);  // it stopped, and stays
  EXPECT_EQ(carried.lane, 1);   // the lane change ended in the target lane
  EXPECT_EQ(carried.target_lane, 1);
  EXPECT_EQ(carried.indicator, Indicator::kOff);
}

TEST(CarriedStates, ASignalEndsAfterAStepAndAControlledActorKeepsItsScriptedIndicator) {
  Vehicle v = moving_vehicle();
  v.lane_change = {0, 1, LaneChangePhase::kSignalling, 0.0, 3.0, 0.0, 0.0};
  v.control.mode = ControlMode::kControlled;
  v.control.indicator = static_cast<std::uint8_t>(Indicator::kRight);
  const VehicleReport before(v, Region::kOuterRear);
  EXPECT_EQ(before.indicator, Indicator::kLeft);  // signalling for the lane to its left
  move_as_meso(v);
  const VehicleReport after = carried_forward(before, kDt_s);
  EXPECT_TRUE(same_state(after, VehicleReport(v, Region::kOuterRear)));
  EXPECT_EQ(after.indicator, Indicator::kRight);  // what the script shows
}

TEST(CarriedStates, SameStateTellsEveryFieldAReaderSeesBitForBit) {
  const VehicleReport a(moving_vehicle(), Region::kOuterFront);
  VehicleReport b = a;
  EXPECT_TRUE(same_state(a, b));
  b.s_m = std::nextafter(a.s_m, 1e9);
  EXPECT_FALSE(same_state(a, b));
  b = a;
  b.region = Region::kInner;
  EXPECT_FALSE(same_state(a, b));
  b = a;
  b.lane_change.phase_elapsed_s += 1e-12;
  EXPECT_FALSE(same_state(a, b));
  b = a;
  b.lane_change.since_last_change_s += 5.0;  // the driver's own timer: not published
  EXPECT_TRUE(same_state(a, b));
}

TEST(CarriedStates, OnlyNewAndChangedStatesArePublishedAndTheTracksRebuildEveryStep) {
  SparseStates publisher(kDt_s);
  StateTracks reader(kDt_s);
  Vehicle a = moving_vehicle();
  a.id = 1;
  a.lane_change = {};
  a.accel_mps2 = 0.5;
  Vehicle b = a;
  b.id = 2;
  b.s_m = 1900.0;
  for (int k = 0; k < 30; ++k) {
    if (k == 10) b.accel_mps2 = -0.2;  // a new plan
    std::vector<VehicleReport> states{VehicleReport(a, Region::kOuterFront)};
    if (k < 20) states.emplace_back(b, Region::kOuterFront);  // b is gone from step 20 on
    const SparseStep sparse = publisher.select(states);
    const std::size_t expected = k == 0 ? 2 : (k == 10 ? 1 : 0);
    EXPECT_EQ(sparse.states.size(), expected) << "step " << k;
    EXPECT_EQ(sparse.gone, k == 20 ? std::vector<VehicleId>{2} : std::vector<VehicleId>{}) << "step " << k;
    const std::vector<VehicleReport>& rebuilt = reader.step(sparse.states, sparse.gone);
    ASSERT_EQ(rebuilt.size(), states.size()) << "step " << k;
    for (std::size_t i = 0; i < states.size(); ++i) EXPECT_TRUE(same_state(rebuilt[i], states[i])) << "step " << k;
    move_as_meso(a);
    move_as_meso(b);
  }
}

TEST(CarriedStates, AVehicleComesBackAsNewAfterItWasGone) {
  SparseStates publisher(kDt_s);
  const VehicleReport a(moving_vehicle(), Region::kOuterRear);
  EXPECT_EQ(publisher.select({a}).states.size(), 1u);
  const SparseStep without = publisher.select({});
  EXPECT_EQ(without.gone, std::vector<VehicleId>{a.id});
  EXPECT_EQ(publisher.select({carried_forward(carried_forward(a, kDt_s), kDt_s)}).states.size(), 1u);  // new again
}

// The whole window's cores over a drive: meso's every state, rebuilt by a reader from the sparse
// ones through the messages the DDS shells send, equals the message meso would publish. (Vehicles
// leave meso in handoffs to micro, to the generator's front zone and to nobody, and join it from
// micro, the generator and the director.)
void expect_meso_rebuilt_from_sparse_states(const std::string& scenario_name, double duration_s,
                                            double max_published_share) {
  const ScenarioConfig sc = testing::shipped_scenario(scenario_name);
  const Road road(sc.road);
  bench::WindowCores cores(sc, sc.seed);
  SparseStates publisher(sc.step_s);
  StateTracks reader(sc.step_s);
  std::uint64_t states = 0;
  std::uint64_t published = 0;
  const Step steps = static_cast<Step>(duration_s / sc.step_s);
  for (Step k = 0; k < steps; ++k) {
    const StepInput in = cores.next_input();
    const bench::StepOutputs out = cores.compute(in);
    const double time_s = static_cast<double>(k) * sc.step_s;
    const SparseStep sparse = publisher.select(out.meso.states);
    std::vector<VehicleReport> received;  // through the messages
    for (const VehicleReport& r : sparse.states) {
      received.push_back(dds::report_from_msg(dds::to_msg(r, bench::kMesoService, k, time_s, road)));
    }
    const std::vector<VehicleReport>& rebuilt = reader.step(received, sparse.gone);
    ASSERT_EQ(rebuilt.size(), out.meso.states.size()) << "step " << k;
    for (std::size_t i = 0; i < rebuilt.size(); ++i) {
      const msg::VehicleState want = dds::to_msg(out.meso.states[i], bench::kMesoService, k, time_s, road);
      ASSERT_EQ(dds::to_msg(rebuilt[i], bench::kMesoService, k, time_s, road), want)
          << scenario_name << " step " << k << " vehicle " << want.id();
    }
    states += out.meso.states.size();
    published += received.size();
    cores.publish(in, out);
  }
  ASSERT_GT(states, 1000u);
  const double share = static_cast<double>(published) / static_cast<double>(states);
  std::printf("%s, %.0f s: meso published %llu of %llu states (%.3f)\n", scenario_name.c_str(), duration_s,
              static_cast<unsigned long long>(published), static_cast<unsigned long long>(states), share);
  EXPECT_LT(share, max_published_share);
}

TEST(CarriedStates, AReaderRebuildsEveryMesoStateOfAFreewayDriveFromTheFewItGets) {
  expect_meso_rebuilt_from_sparse_states("freeway", 120.0, 0.15);
}

TEST(CarriedStates, AReaderRebuildsEveryMesoStateOfARuralDriveWithPassesFromTheFewItGets) {
  expect_meso_rebuilt_from_sparse_states("rural", 120.0, 0.2);
}

}  // namespace
}  // namespace entourage
