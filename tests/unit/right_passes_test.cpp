// The director bench's count of the vehicles the ego passed on the right (tests/bench/play_runs.hpp,
// RightPassCounter): a pass counts when the ego, in a lane right of a vehicle's, goes from behind
// it to ahead of it with neither changing lanes meanwhile.
#include <gtest/gtest.h>

#include <vector>

#include "core_test_util.hpp"
#include "director_test_util.hpp"
#include "play_runs.hpp"

namespace entourage::bench {
namespace {

using testing::ego_at;
using testing::vehicle;

// The ego at 30 m/s in `ego_lane` from s 1000 on, the vehicle `v` at 20 m/s from s 1040 on, over
// `steps` steps of 0.1 s; `change_at`: the step the vehicle starts a lane change (-1: never).
RightPasses drive(int ego_lane, ObservedVehicle v, int steps, int change_at = -1, int to_lane = 0) {
  RightPassCounter counter;
  RightPasses passes;
  for (int k = 0; k < steps; ++k) {
    const double t = 0.1 * k;
    const EgoObservation ego = ego_at(k, 1000.0 + 30.0 * t, 30.0, ego_lane);
    v.s_m = 1040.0 + 20.0 * t;
    if (change_at >= 0 && k >= change_at) v.target_lane = to_lane;
    counter.observe(ego, {v}, passes);
  }
  return passes;
}

TEST(RightPasses, TheEgoOvertakingAVehicleInTheLaneLeftOfItsOwnCountsOnce) {
  // 40 m to make up at 10 m/s: passed after 4 s, counted once in 8 s.
  const RightPasses autonomous = drive(0, vehicle(1, 1040.0, 20.0, 1), 80);
  EXPECT_EQ(autonomous.autonomous, 1);
  EXPECT_EQ(autonomous.commanded, 0);
  ObservedVehicle moved = vehicle(2, 1040.0, 20.0, 1);
  moved.control = ControlMode::kTransported;
  const RightPasses commanded = drive(0, moved, 80);
  EXPECT_EQ(commanded.commanded, 1);
  EXPECT_EQ(commanded.total(), 1);
}

TEST(RightPasses, NoneOnTheLeftInTheEgosOwnLaneBeforeTheEgoIsLevelOrAcrossALaneChange) {
  EXPECT_EQ(drive(1, vehicle(1, 1040.0, 20.0, 0), 80).total(), 0);  // passed on the left
  EXPECT_EQ(drive(1, vehicle(2, 1040.0, 20.0, 1), 80).total(), 0);  // its own lane: no pass counted
  EXPECT_EQ(drive(0, vehicle(3, 1040.0, 20.0, 1), 30).total(), 0);  // still behind it
  // The vehicle starts moving into the ego's lane before the ego is level with it.
  EXPECT_EQ(drive(0, vehicle(4, 1040.0, 20.0, 1), 80, 20, 0).total(), 0);
}

}  // namespace
}  // namespace entourage::bench
