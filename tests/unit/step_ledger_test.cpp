// Lockstep bookkeeping: a step is complete only when every peer reported it and every sample it
// announced has arrived, whatever the arrival order.
#include <gtest/gtest.h>

#include "dds/step_ledger.hpp"

namespace entourage::dds {
namespace {

constexpr ServiceId kEgo{Role::kEgo, 0};
constexpr ServiceId kMicro{Role::kMicro, 0};
constexpr ServiceId kMeso{Role::kMeso, 0};

TopicCounts counts(std::uint32_t vehicles, std::uint32_t handoffs = 0) {
  TopicCounts c{};
  c[static_cast<std::size_t>(Topic::kVehicleState)] = vehicles;
  c[static_cast<std::size_t>(Topic::kHandoff)] = handoffs;
  return c;
}

const TopicMask kWorld = mask_of(Topic::kVehicleState) | mask_of(Topic::kHandoff);

TEST(StepLedger, CompleteWhenAllPeersReportedAndAllSamplesArrived) {
  StepLedger l({kEgo, kMicro, kMeso}, kMicro);
  l.on_step_done(kEgo, 4, counts(0));
  EXPECT_FALSE(l.complete(4, kWorld));  // meso not heard from
  l.on_sample(kMeso, 4, Topic::kVehicleState);
  l.on_step_done(kMeso, 4, counts(2, 1));
  EXPECT_FALSE(l.complete(4, kWorld));  // one of two vehicle states, no handoff yet
  l.on_sample(kMeso, 4, Topic::kHandoff);
  l.on_sample(kMeso, 4, Topic::kVehicleState);
  EXPECT_TRUE(l.complete(4, kWorld));
  EXPECT_FALSE(l.complete(5, kWorld));
}

// The inbox wakes its waiter only for a report or for the sample that completes one (a wake per
// sample cost every service a thread switch per vehicle state): whatever the order, the event that
// makes a step complete is one of those.
TEST(StepLedger, OnlyTheLastAnnouncedSampleAfterItsReportCompletesIt) {
  StepLedger l({kEgo, kMicro, kMeso}, kMicro);
  l.on_step_done(kEgo, 4, counts(0));
  EXPECT_FALSE(l.on_sample(kMeso, 4, Topic::kVehicleState)) << "before its report";
  l.on_step_done(kMeso, 4, counts(3, 1));
  EXPECT_FALSE(l.on_sample(kMeso, 4, Topic::kVehicleState)) << "the second of three";
  EXPECT_FALSE(l.complete(4, kWorld));
  EXPECT_TRUE(l.on_sample(kMeso, 4, Topic::kVehicleState)) << "the third of three";
  EXPECT_FALSE(l.complete(4, kWorld)) << "the handoff is still missing";
  EXPECT_TRUE(l.on_sample(kMeso, 4, Topic::kHandoff));
  EXPECT_TRUE(l.complete(4, kWorld));
  EXPECT_FALSE(l.on_sample(kMeso, 4, Topic::kVehicleState)) << "one more than announced completes nothing new";
  // All samples before the report: the report is the event that completes the step.
  l.on_sample(kMeso, 5, Topic::kVehicleState);
  l.on_step_done(kEgo, 5, counts(0));
  EXPECT_FALSE(l.complete(5, kWorld));
  l.on_step_done(kMeso, 5, counts(1));
  EXPECT_TRUE(l.complete(5, kWorld));
}

TEST(StepLedger, SamplesOnTopicsNotWaitedForDoNotMatter) {
  StepLedger l({kEgo, kMeso}, kEgo);
  l.on_step_done(kMeso, 1, counts(3, 2));
  for (int i = 0; i < 3; ++i) l.on_sample(kMeso, 1, Topic::kVehicleState);
  EXPECT_TRUE(l.complete(1, mask_of(Topic::kVehicleState)));
  EXPECT_FALSE(l.complete(1, kWorld));
}

TEST(StepLedger, SelfIsNotWaitedFor) {
  StepLedger l({kEgo, kMicro}, kMicro);
  l.on_step_done(kEgo, 0, counts(0));
  EXPECT_TRUE(l.complete(0, kWorld));
}

TEST(StepLedger, MissingNamesWhoAndWhat) {
  StepLedger l({kEgo, kMicro, kMeso}, kEgo);
  l.on_step_done(kMeso, 7, counts(2));
  l.on_sample(kMeso, 7, Topic::kVehicleState);
  const std::string m = l.missing(7, kWorld);
  EXPECT_NE(m.find("micro (no step report)"), std::string::npos) << m;
  EXPECT_NE(m.find("meso (1/2 entourage/vehicle_state)"), std::string::npos) << m;
}

TEST(StepLedger, ForgetDropsOldSteps) {
  StepLedger l({kEgo, kMeso}, kEgo);
  l.on_step_done(kMeso, 1, counts(0));
  l.on_step_done(kMeso, 2, counts(0));
  l.forget_before(2);
  EXPECT_FALSE(l.reported(kMeso, 1));
  EXPECT_TRUE(l.reported(kMeso, 2));
}

}  // namespace
}  // namespace entourage::dds
