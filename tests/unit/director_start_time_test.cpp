// The event director's start-time estimation (paper IV): the extrapolation of the ego's speed
// and acceleration, and the drive behind a leader the ego cannot pass; the leader it is given;
// the ego's usual speed (RecentTop), against which an estimate made while it holds a lower speed
// is not trusted to give an actor up (play.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "behaviour/idm.hpp"
#include "core_test_util.hpp"
#include "director/core/recent_top.hpp"
#include "director/core/stage.hpp"
#include "director/core/start_time.hpp"
#include "director_test_util.hpp"

namespace entourage::director {
namespace {

using testing::vehicle;

// --- Start-time estimation

TEST(StartTime, AtConstantSpeedItIsDistanceOverSpeed) {
  StartTimeEstimator e;
  for (int i = 0; i < 50; ++i) e.observe(25.0, 0.0, 0.1);
  const Prediction p = e.predict(1000.0);
  EXPECT_NEAR(p.time_s, 40.0, 0.01);
  EXPECT_NEAR(p.speed_mps, 25.0, 1e-9);
}

TEST(StartTime, ADriverWhoKeepsAcceleratingAsExpectedArrivesWhenPredicted) {
  // The model's own case: acceleration a fading out over tau. Simulate it and compare.
  const StartTimeParams params{5.0, 2.0, 1.0, 3600.0};
  StartTimeEstimator e(params);
  for (int i = 0; i < 100; ++i) e.observe(20.0, 1.0, 0.1);  // the filter has settled on 1 m/s^2
  const Prediction p = e.predict(800.0);
  double s = 0.0, t = 0.0;
  const double dt = 0.001;
  while (s < 800.0) {
    s += dt * (20.0 + 1.0 * 5.0 * (1.0 - std::exp(-t / 5.0)));
    t += dt;
  }
  EXPECT_NEAR(p.time_s, t, 0.05);
  EXPECT_LT(p.time_s, 800.0 / 20.0);  // earlier than at the present speed
  EXPECT_NEAR(p.speed_mps, 25.0, 0.1);  // 20 + a tau
}

TEST(StartTime, ABrakingDriverMovesTheEstimateLaterAndAStandingOneMakesItUnknown) {
  StartTimeEstimator e;
  for (int i = 0; i < 50; ++i) e.observe(25.0, 0.0, 0.1);
  const double before = e.predict(1000.0).time_s;
  for (int i = 0; i < 20; ++i) e.observe(25.0 - 0.3 * i, -3.0, 0.1);
  EXPECT_GT(e.predict(1000.0).time_s, before + 5.0);
  StartTimeEstimator stopped(StartTimeParams{5.0, 2.0, 0.0, 3600.0});
  stopped.observe(0.0, 0.0, 0.1);
  EXPECT_LT(stopped.predict(100.0).time_s, 0.0);
}

TEST(StartTime, BehindASlowerLeaderTheEgoIsExpectedToSlowDownAsAnIdmDriverAndArriveLater) {
  StartTimeEstimator e;
  for (int i = 0; i < 50; ++i) e.observe(24.0, 0.0, 0.1);
  const Prediction free = e.predict(600.0);
  const LeaderAhead truck{200.0, 16.0};
  const Prediction behind = e.predict(600.0, truck);
  // The same driver integrated finely: the reference parameters, desired speed its present one.
  IdmParams q = StartTimeParams{}.follower;
  q.desired_speed_mps = 24.0;
  double x = 0.0, v = 24.0, t = 0.0;
  const double dt = 0.001;
  while (x < 600.0) {
    const double a = idm_accel_mps2(q, v, truck.gap_m + truck.speed_mps * t - x, truck.speed_mps);
    x += v * dt;
    v = std::max(0.0, v + a * dt);
    t += dt;
  }
  EXPECT_NEAR(behind.time_s, t, 0.1);
  EXPECT_NEAR(behind.speed_mps, v, 0.2);
  EXPECT_GT(behind.time_s, free.time_s + 1.0);  // 25 s at its present speed
  EXPECT_LT(behind.speed_mps, 21.0);
  EXPECT_GT(behind.speed_mps, 16.0);
}

TEST(StartTime, AFasterOrNoLeaderLeavesTheEstimateAndAStandingOneShortOfTheDistanceMakesItUnknown) {
  StartTimeEstimator e;
  for (int i = 0; i < 50; ++i) e.observe(24.0, 0.0, 0.1);
  const double free = e.predict(600.0).time_s;
  EXPECT_DOUBLE_EQ(e.predict(600.0, std::nullopt).time_s, free);
  EXPECT_NEAR(e.predict(600.0, LeaderAhead{100.0, 30.0}).time_s, free, 0.01);
  EXPECT_LT(e.predict(600.0, LeaderAhead{100.0, 0.0}).time_s, 0.0);
  // Standing beyond the distance: the ego gets there, slowing down.
  EXPECT_GT(e.predict(600.0, LeaderAhead{700.0, 0.0}).time_s, free);
}

TEST(Staging, TheEgosUnpassableLeaderIsTheNearestAheadInItsLaneWhereItsDirectionHasOneLane) {
  const EgoObservation ego = testing::ego_at(0, 1000.0, 24.0);
  const std::vector<ObservedVehicle> world = {
      vehicle(1, 1300.0, 20.0), vehicle(2, 1150.0, 16.0), vehicle(3, 1100.0, 22.0, 0, Direction::kBackward),
      vehicle(4, 950.0, 25.0)};
  const ObservedVehicle* leader = unpassable_leader(ego, world, Lanes{1, 1});
  ASSERT_NE(leader, nullptr);
  EXPECT_EQ(leader->id, 2u);
  const LeaderAhead seen = leader_ahead(ego, *leader, 16.0);
  EXPECT_NEAR(seen.gap_m, 150.0 - 0.5 * (4.5 + ego.length_m), 1e-9);
  EXPECT_DOUBLE_EQ(seen.speed_mps, 16.0);
  EXPECT_EQ(unpassable_leader(ego, world, Lanes{2, 0}), nullptr);  // it changes lanes instead
  EgoObservation overtaking = ego;
  overtaking.lane = overtaking.target_lane = 1;  // in the oncoming lane
  EXPECT_EQ(unpassable_leader(overtaking, world, Lanes{1, 1}), nullptr);
  const std::vector<ObservedVehicle> behind_only = {vehicle(4, 950.0, 25.0)};
  EXPECT_EQ(unpassable_leader(ego, behind_only, Lanes{1, 1}), nullptr);
}

TEST(RecentTop, TheHighestValueWithinTheWindowAndNoOlder) {
  RecentTop top(30.0);
  EXPECT_DOUBLE_EQ(top.top(), 0.0);
  top.observe(0.0, 25.0);
  top.observe(10.0, 15.0);  // slowed: the 25 of 10 s ago is still the usual speed
  EXPECT_DOUBLE_EQ(top.top(), 25.0);
  top.observe(30.0, 15.0);
  EXPECT_DOUBLE_EQ(top.top(), 25.0);  // exactly 30 s ago: still within
  top.observe(30.5, 16.0);
  EXPECT_DOUBLE_EQ(top.top(), 16.0);  // 25 is older than the window; 16 is above the 15 since
  top.observe(40.0, 12.0);
  EXPECT_DOUBLE_EQ(top.top(), 16.0);
  top.observe(61.0, 11.0);
  EXPECT_DOUBLE_EQ(top.top(), 12.0);
}

}  // namespace
}  // namespace entourage::director
