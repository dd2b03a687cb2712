// The director bench's measure of an actor held up in its lane (tests/bench/play_runs.hpp,
// leader_gap): the nearest vehicle ahead of it in its lane, the ego included, the gap bumper to
// bumper, and whether that one is under a director's command.
#include <gtest/gtest.h>

#include <vector>

#include "core_test_util.hpp"
#include "director_test_util.hpp"
#include "play_runs.hpp"

namespace entourage::bench {
namespace {

using testing::vehicle;

TEST(LeaderGap, TheNearestVehicleAheadInTheLaneWithItsGapAndWhetherTheDirectorCommandsIt) {
  const ObservedVehicle actor = vehicle(1, 1000.0, 25.0, 1);
  ObservedVehicle cleared = vehicle(2, 1030.0, 20.0, 1);  // 30 m ahead, centre to centre
  cleared.control = ControlMode::kTransported;
  const ObservedVehicle farther = vehicle(3, 1100.0, 20.0, 1);
  const ObservedVehicle beside = vehicle(4, 1010.0, 20.0, 0);  // another lane
  const ObservedVehicle behind = vehicle(5, 990.0, 30.0, 1);
  const EgoObservation ego = testing::ego_at(0, 1200.0, 25.0, 0);  // in the other lane
  const std::vector<ObservedVehicle> world{actor, cleared, farther, beside, behind};
  const auto lead = leader_gap(actor, world, ego);
  ASSERT_TRUE(lead.has_value());
  EXPECT_NEAR(lead->gap_m, 30.0 - 4.5, 1e-9);  // two cars of 4.5 m
  EXPECT_TRUE(lead->commanded);
  // An autonomous leader is not the director's.
  const std::vector<ObservedVehicle> autonomous{actor, farther};
  EXPECT_FALSE(leader_gap(actor, autonomous, ego)->commanded);
  // Nobody ahead in its lane.
  EXPECT_FALSE(leader_gap(actor, {actor, beside, behind}, ego).has_value());
}

TEST(LeaderGap, TheEgoAheadInTheLaneIsALeaderNotUnderACommand) {
  const ObservedVehicle actor = vehicle(1, 1000.0, 25.0, 0);
  EgoObservation ego = testing::ego_at(0, 1020.0, 25.0, 0);
  ego.length_m = 4.5;
  ObservedVehicle cleared = vehicle(2, 1050.0, 20.0, 0);
  cleared.control = ControlMode::kTransported;
  const auto lead = leader_gap(actor, {actor, cleared}, ego);
  ASSERT_TRUE(lead.has_value());
  EXPECT_NEAR(lead->gap_m, 20.0 - 4.5, 1e-9);
  EXPECT_FALSE(lead->commanded);
  // The ego in another lane, or behind: the vehicle ahead is the leader.
  ego.lane = ego.target_lane = 1;
  EXPECT_TRUE(leader_gap(actor, {actor, cleared}, ego)->commanded);
}

}  // namespace
}  // namespace entourage::bench
