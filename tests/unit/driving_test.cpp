// A driver's whole decision in hand-built situations: speed adaptation, the Human Driver Model's
// delay, mandatory lane changes at a closure, and entry behind an oncoming overtaker. The overtaking
// manoeuvre has its own file (overtaking_manoeuvre_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core_test_util.hpp"
#include "mini_world.hpp"
#include "traffic/driving.hpp"
#include "traffic/entry.hpp"
#include "traffic/lane_changes.hpp"
#include "traffic/world.hpp"

namespace entourage {
namespace {

using testing::car;
using testing::MiniWorld;

TEST(SpeedAdaptationInDriving, SlowsDownInTimeForALowerLimitAhead) {
  ScenarioConfig sc = testing::road_scenario(1, 0);
  sc.road.speed_zones.push_back({3000.0, 4000.0, 70.0 / 3.6});
  MiniWorld w(sc);
  w.vehicles.push_back(car(1, Direction::kForward, 0, 1000.0, 33.0, 33.3));
  double speed_at_zone = -1.0;
  while (w.get(1).s_m < 3500.0) {
    w.step();
    if (speed_at_zone < 0.0 && w.get(1).s_m >= 3000.0) speed_at_zone = w.get(1).speed_mps;
  }
  // The median driver of its own type (median = its own desired speed) drives at the limit.
  EXPECT_LT(speed_at_zone, 70.0 / 3.6 + 1.0);
  EXPECT_NEAR(w.get(1).speed_mps, 70.0 / 3.6, 0.5);
}

TEST(SpeedAdaptationInDriving, FastDriversAreSlowedMoreThanSlowOnes) {
  ScenarioConfig sc = testing::road_scenario(1, 0);
  sc.road.speed_zones.push_back({0.0, 10000.0, 90.0 / 3.6});
  const DrivingEnvironment env(sc);
  Vehicle fast = car(1, Direction::kForward, 0, 5000.0, 30.0, 140.0 / 3.6);
  Vehicle slow = car(2, Direction::kForward, 0, 5000.0, 30.0, 100.0 / 3.6);
  fast.driver.desired_speed_median_mps = slow.driver.desired_speed_median_mps = 120.0 / 3.6;
  const double fast_loss = fast.driver.desired_speed_mps() - local_params(fast, env).idm.desired_speed_mps;
  const double slow_loss = slow.driver.desired_speed_mps() - local_params(slow, env).idm.desired_speed_mps;
  EXPECT_GT(fast_loss, slow_loss + 3.0);
  EXPECT_GT(slow_loss, 0.0);
}

TEST(HumanDriverInDriving, TheAppliedAccelerationIsTheDecisionOfTheReactionTimeAgo) {
  const ScenarioConfig sc = testing::road_scenario(1, 0);
  const DrivingEnvironment env(sc);
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 20.0, 30.0);
  v.driver.car_following.human_driver = true;
  v.driver.car_following.hdm.reaction_time_s = 0.3;
  v.driver.car_following.hdm.distance_error = 0.0;
  v.driver.car_following.hdm.inverse_ttc_error_per_s = 0.0;
  for (double a : {0.1, 0.2, 0.3, 0.4}) v.hdm_memory.push(a);  // newest 0.4
  LaneIndex index(1, 0);
  add_to_index(index, Direction::kForward, 0, 0, 1, 1000.0, 20.0, 0.0, 4.5);
  index.sort();
  const Decision d = decide(v, index, env);
  EXPECT_NEAR(d.hdm_decided_mps2, idm_free_accel_mps2(v.driver.car_following.idm, 20.0), 1e-12);
  EXPECT_NEAR(d.accel_mps2, 0.2, 1e-6);  // three steps ago
  Vehicle after = v;
  commit(after, d, env.dt_s());
  EXPECT_NEAR(after.hdm_memory.decided_mps2[0], d.hdm_decided_mps2, 1e-6);
  EXPECT_NE(after.driver.rng_state, v.driver.rng_state);  // the error processes drew from the driver's stream
}

TEST(MandatoryLaneChange, LeavesAClosedLaneWithoutWaitingForTheInterval) {
  ScenarioConfig sc = testing::road_scenario(2, 0);
  sc.road.lane_closures.push_back({Direction::kForward, 0, 1400.0, 2000.0});
  MiniWorld w(sc);
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 25.0, 25.0);
  v.lane_change.since_last_change_s = 0.0;  // just changed: a discretionary change would wait
  w.vehicles.push_back(v);
  const std::vector<Decision> d = w.decide_all();
  EXPECT_EQ(d[0].lane_change.phase, LaneChangePhase::kSignalling);
  EXPECT_EQ(d[0].lane_change.to_lane, 1);
  EXPECT_TRUE(d[0].mandatory_change);
  for (int i = 0; i < 200; ++i) w.step();
  EXPECT_EQ(w.get(1).lane, 1);
}

TEST(MandatoryLaneChange, NobodyChangesIntoAClosedLane) {
  ScenarioConfig sc = testing::road_scenario(2, 0);
  sc.road.lane_closures.push_back({Direction::kForward, 0, 1400.0, 2000.0});
  const DrivingEnvironment env(sc);
  Vehicle v = car(1, Direction::kForward, 1, 1000.0, 25.0, 25.0);  // free, the right bias pulls right
  EXPECT_FALSE(lane_allowed(v, 0, env));
  v.s_m = 2100.0;  // past the closure
  EXPECT_TRUE(lane_allowed(v, 0, env));
}

TEST(MandatoryLaneChange, StopsBeforeTheClosureWhenTheOtherLaneIsFull) {
  ScenarioConfig sc = testing::road_scenario(2, 0);
  sc.road.lane_closures.push_back({Direction::kForward, 0, 1300.0, 2000.0});
  MiniWorld w(sc);
  w.vehicles.push_back(car(1, Direction::kForward, 0, 1000.0, 20.0, 25.0));
  // A column of stopped vehicles beside it in lane 1, past the closure, with no gap to merge into.
  for (VehicleId id = 2; id < 110; ++id) {
    Vehicle q = car(id, Direction::kForward, 1, 850.0 + 6.0 * (id - 2), 0.0, 0.1, LaneChangeModel::kNone);
    w.vehicles.push_back(q);
  }
  for (int i = 0; i < 600; ++i) w.step();
  EXPECT_EQ(w.get(1).lane, 0);
  EXPECT_LT(w.get(1).s_m + 0.5 * w.get(1).length_m, 1300.0);
  EXPECT_NEAR(w.get(1).speed_mps, 0.0, 0.05);
}

TEST(Entry, NothingEntersALaneAnOvertakerOfTheOtherDirectionComesDown) {
  // An oncoming car overtakes in the forward lane (backward lane 1) 300 m ahead of the rear edge:
  // a forward vehicle born there now would meet it head-on within seconds.
  VehicleTypeConfig type;
  type.length_m = 4.5;
  IdmParams driver;
  LaneIndex index(1, 1);
  const double edge_m = 1000.0;
  EXPECT_TRUE(find_entry(index, Direction::kForward, edge_m, 25.0, type, driver).has_value());
  add_to_index(index, Direction::kBackward, 1, 1, 9, -(edge_m + 300.0), 25.0, 0.0, 4.5);
  index.sort();
  EXPECT_FALSE(find_entry(index, Direction::kForward, edge_m, 25.0, type, driver).has_value());
  // Once it is behind the edge, the lane is free again.
  LaneIndex later(1, 1);
  add_to_index(later, Direction::kBackward, 1, 1, 9, -(edge_m - 50.0), 25.0, 0.0, 4.5);
  later.sort();
  EXPECT_TRUE(find_entry(later, Direction::kForward, edge_m, 25.0, type, driver).has_value());
}

}  // namespace
}  // namespace entourage
