// The oncoming traffic beyond the window's front edge (traffic/unseen_oncoming.hpp): one stand-in
// per oncoming lane of a two-way road, the oncoming demand's mean spacing beyond the edge, that a
// driver considering a pass finds as its nearest oncoming vehicle where none of the window's is
// nearer.
#include <gtest/gtest.h>

#include "core_test_util.hpp"
#include "traffic/unseen_oncoming.hpp"
#include "traffic/world.hpp"

namespace entourage {
namespace {

TEST(UnseenOncoming, ATwoWayRoadHasOneStandInPerOncomingLaneAtTheDemandsMeanSpacing) {
  const ScenarioConfig rural = testing::shipped_scenario("rural");
  const UnseenOncoming u = unseen_oncoming(rural);
  ASSERT_TRUE(u.present);
  EXPECT_EQ(u.lanes, 1);
  // 90 km/h and 450 vehicles an hour: 200 m apart.
  EXPECT_NEAR(u.speed_mps, 25.0, 1e-9);
  EXPECT_NEAR(u.beyond_edge_m, 200.0, 1e-9);
  // A freeway has a barrier: nobody passes in the oncoming carriageway.
  EXPECT_FALSE(unseen_oncoming(testing::freeway_scenario()).present);
  // Nor is there a stand-in without oncoming demand.
  ScenarioConfig one_way = rural;
  one_way.backward.flow_veh_per_s = 0.0;
  EXPECT_FALSE(unseen_oncoming(one_way).present);
}

TEST(UnseenOncoming, APassingDriverMeetsTheStandInWhereNoOncomingVehicleOfTheWindowIsNearer) {
  const UnseenOncoming u = unseen_oncoming(testing::shipped_scenario("rural"));
  LaneIndex index(1, 1);
  index.sort();
  const double front_edge_s_m = 2000.0;
  // From the forward lane's point of view the oncoming lane is lane 1.
  EXPECT_EQ(index.oncoming(Direction::kForward, 1, 1000.0), nullptr);
  add_unseen_oncoming(index, u, front_edge_s_m);
  const Occupant* stand_in = index.oncoming(Direction::kForward, 1, 1000.0);
  ASSERT_NE(stand_in, nullptr);
  EXPECT_EQ(stand_in->id, kUnseenOncomingFirstId);
  EXPECT_NEAR(oncoming_gap(*stand_in, 1000.0, 4.5), 2200.0 - 1000.0 - 4.5, 1e-9);
  // An oncoming vehicle of the window nearer than it is the one met.
  LaneIndex with_one(1, 1);
  add_to_index(with_one, Direction::kBackward, 0, 0, 7, -1500.0, 22.0, 0.0, 4.5);
  with_one.sort();
  add_unseen_oncoming(with_one, u, front_edge_s_m);
  const Occupant* nearest = with_one.oncoming(Direction::kForward, 1, 1000.0);
  ASSERT_NE(nearest, nullptr);
  EXPECT_EQ(nearest->id, 7u);
  // Nothing is added where there is no stand-in.
  LaneIndex freeway(2, 2);
  add_unseen_oncoming(freeway, unseen_oncoming(testing::freeway_scenario()), front_edge_s_m);
  EXPECT_EQ(freeway.oncoming(Direction::kForward, 2, 1000.0), nullptr);
}

}  // namespace
}  // namespace entourage
