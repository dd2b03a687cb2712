// The director bench's count of lane changes made in view while a play is prepared
// (tests/bench/play_runs.hpp, LaneChangeCounter): per kind (under a director's transport command,
// autonomous), with the most one vehicle made in the run.
#include <gtest/gtest.h>

#include "director_test_util.hpp"
#include "play_runs.hpp"

namespace entourage::bench {
namespace {

using testing::vehicle;

ObservedVehicle in_lane(VehicleId id, int lane, ControlMode control) {
  ObservedVehicle v = vehicle(id, 1000.0, 25.0, lane);
  v.control = control;
  return v;
}

TEST(LaneChangesMade, AVehicleSentBackAndForthCountsEachChangeAndIsTheRunsMost) {
  LaneChangeCounter counter;
  const double dt = 0.1;
  // Vehicle 1, commanded, changes lanes four times; vehicle 2, autonomous, once.
  for (const int lane : {0, 0, 1, 1, 0, 1, 0}) counter.observe(in_lane(1, lane, ControlMode::kTransported), dt);
  for (const int lane : {1, 0, 0}) counter.observe(in_lane(2, lane, ControlMode::kAutonomous), dt);
  const LaneChangesMade commanded = counter.commanded();
  const LaneChangesMade autonomous = counter.autonomous();
  EXPECT_EQ(commanded.count, 4);
  EXPECT_EQ(commanded.most_by_one, 4);
  EXPECT_EQ(commanded.runs_with_many, 1);
  EXPECT_NEAR(commanded.vehicle_s, 0.7, 1e-9);
  EXPECT_NEAR(commanded.per_vehicle_hour(), 3600.0 * 4 / 0.7, 1e-6);
  EXPECT_EQ(autonomous.count, 1);
  EXPECT_EQ(autonomous.runs_with_many, 0);
  // Over runs: counts and runs add up, the most is the largest.
  LaneChangesMade runs = commanded;
  runs.add(autonomous);
  EXPECT_EQ(runs.count, 5);
  EXPECT_EQ(runs.most_by_one, 4);
  EXPECT_EQ(runs.runs_with_many, 1);
}

TEST(LaneChangesMade, AChangeOfKindOrOutOfViewIsNoLaneChangeMade) {
  LaneChangeCounter counter;
  // Autonomous in lane 0, then commanded in lane 1: its control changed, not a change it made as either.
  counter.observe(in_lane(1, 0, ControlMode::kAutonomous), 0.1);
  counter.observe(in_lane(1, 1, ControlMode::kTransported), 0.1);
  // Out of view (forgotten) in lane 0 and back in view in lane 1.
  counter.forget(1);
  counter.observe(in_lane(1, 0, ControlMode::kTransported), 0.1);
  // Controlled by a script: neither kind, and forgotten.
  counter.observe(in_lane(1, 1, ControlMode::kControlled), 0.1);
  counter.observe(in_lane(1, 0, ControlMode::kTransported), 0.1);
  EXPECT_EQ(counter.commanded().count, 0);
  EXPECT_EQ(counter.autonomous().count, 0);
  EXPECT_NEAR(counter.commanded().vehicle_s, 0.3, 1e-9);
}

}  // namespace
}  // namespace entourage::bench
