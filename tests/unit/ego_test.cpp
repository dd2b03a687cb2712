// The ego stand-in's drivers.
#include <gtest/gtest.h>

#include "core_test_util.hpp"
#include "ego/core/ego_core.hpp"

namespace entourage {
namespace {

using entourage::testing::minimal_scenario;

ObservedVehicle stopped_car(double s, int lane = 0) {
  ObservedVehicle o;
  o.id = 7;
  o.s_m = s;
  o.lane = o.target_lane = lane;
  o.length_m = 4.5;
  return o;
}

TEST(EgoCore, AnIdmDriverReachesItsDesiredSpeedOnAFreeRoad) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.start_speed_mps = 10.0;
  ego::EgoCore core(sc);
  EgoObservation e = core.initial();
  EXPECT_DOUBLE_EQ(e.speed_mps, 10.0);
  for (Step k = 1; k <= 1200; ++k) e = core.step(k, {});
  EXPECT_NEAR(e.speed_mps, sc.ego.driver.desired_speed_mps, 0.5);
  EXPECT_EQ(e.step, 1200U);
  EXPECT_NEAR(e.time_s, 120.0, 1e-9);
}

TEST(EgoCore, StopsBehindAStoppedCarWhenItCannotChangeLane) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.driver.lane_changes = false;
  ego::EgoCore core(sc);
  EgoObservation e = core.initial();
  const ObservedVehicle blocker = stopped_car(sc.ego.start_s_m + 500.0);
  for (Step k = 1; k <= 1200; ++k) e = core.step(k, {blocker});
  EXPECT_LT(e.speed_mps, 0.1);
  EXPECT_LT(e.s_m, blocker.s_m - 0.5 * (4.5 + e.length_m));
  EXPECT_GT(e.s_m, blocker.s_m - 20.0);  // and not miles before it
}

TEST(EgoCore, ATransparentEgoDrivesThroughAStoppedCar) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.driver.lane_changes = false;
  sc.ego.transparent = true;
  ego::EgoCore core(sc);
  EgoObservation e = core.initial();
  const ObservedVehicle blocker = stopped_car(sc.ego.start_s_m + 500.0);
  for (Step k = 1; k <= 1200; ++k) e = core.step(k, {blocker});
  EXPECT_NEAR(e.speed_mps, sc.ego.driver.desired_speed_mps, 0.5);
  EXPECT_GT(e.s_m, blocker.s_m + 100.0);
}

TEST(EgoCore, ChangesLaneAroundAStoppedCarWhenItMay) {
  ScenarioConfig sc = minimal_scenario();
  ego::EgoCore core(sc);
  EgoObservation e = core.initial();
  const ObservedVehicle blocker = stopped_car(sc.ego.start_s_m + 300.0);
  bool changed = false;
  for (Step k = 1; k <= 600; ++k) {
    e = core.step(k, {blocker});
    changed = changed || e.target_lane == 1 || e.lane == 1;
  }
  EXPECT_TRUE(changed);
  EXPECT_GT(e.s_m, blocker.s_m);
}

TEST(EgoCore, OvertakesASlowTruckInTheOncomingLaneOnARuralRoad) {
  ScenarioConfig sc = testing::road_scenario(1, 1, RoadKind::kRural);
  sc.ego.driver.desired_speed_mps = 25.0;
  sc.ego.start_speed_mps = 20.0;
  ego::EgoCore core(sc, 7);
  EgoObservation e = core.initial();
  ObservedVehicle truck = stopped_car(sc.ego.start_s_m + 60.0);
  truck.length_m = 16.5;
  truck.speed_mps = 16.0;
  bool used_oncoming_lane = false;
  for (Step k = 1; k <= 900; ++k) {
    e = core.step(k, {truck});
    truck.s_m += truck.speed_mps * sc.step_s;
    used_oncoming_lane = used_oncoming_lane || e.target_lane == 1;
  }
  EXPECT_TRUE(used_oncoming_lane);
  EXPECT_EQ(e.lane, 0);
  EXPECT_GT(e.s_m, truck.s_m + 20.0);
}

TEST(EgoCore, StaysInItsLaneOnARuralRoadWithoutLaneChanges) {
  ScenarioConfig sc = testing::road_scenario(1, 1, RoadKind::kRural);
  sc.ego.driver.desired_speed_mps = 25.0;
  sc.ego.driver.lane_changes = false;
  ego::EgoCore core(sc, 7);
  EgoObservation e = core.initial();
  ObservedVehicle truck = stopped_car(sc.ego.start_s_m + 60.0);
  truck.length_m = 16.5;
  truck.speed_mps = 16.0;
  for (Step k = 1; k <= 900; ++k) {
    e = core.step(k, {truck});
    truck.s_m += truck.speed_mps * sc.step_s;
    ASSERT_EQ(e.target_lane, 0);
  }
  EXPECT_LT(e.s_m, truck.s_m);
}

TEST(EgoCore, StopsForAsLongAsTheScenarioSaysThenDrivesOn) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.driver.stops = {{10.0, 60.0}};
  ego::EgoCore core(sc);
  EgoObservation e = core.initial();
  double stood_s = 0.0;
  double first_standstill_s = -1.0;
  double hardest_brake = 0.0;
  for (Step k = 1; k <= 1500; ++k) {
    e = core.step(k, {});
    hardest_brake = std::min(hardest_brake, e.accel_mps2);
    if (e.speed_mps == 0.0) {
      stood_s += sc.step_s;
      if (first_standstill_s < 0.0) first_standstill_s = e.time_s;
    }
    if (e.time_s < 10.0) {
      ASSERT_GT(e.speed_mps, 0.0);
    }
  }
  // From 30.6 m/s at 1.5 m/s^2: standing after about 20 s, for 60 s, then away again.
  EXPECT_NEAR(first_standstill_s, 10.0 + sc.ego.driver.desired_speed_mps / 1.5, 0.5);
  EXPECT_NEAR(stood_s, 60.0, 0.3);
  EXPECT_GE(hardest_brake, -sc.ego.driver.comfort_decel_mps2 - 1e-9);
  EXPECT_GT(e.speed_mps, 10.0);
  EXPECT_EQ(e.target_lane, e.lane);
}

TEST(EgoCore, FollowsASpeedProfile) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.driver.use_speed_profile = true;
  sc.ego.driver.profile = {{0.0, 20.0}, {1500.0, 20.0}, {1600.0, 10.0}, {9000.0, 10.0}};
  ego::EgoCore core(sc);
  EgoObservation e = core.initial();
  EXPECT_DOUBLE_EQ(e.speed_mps, 20.0);
  for (Step k = 1; k <= 1500 && e.s_m < 2200.0; ++k) e = core.step(k, {});
  EXPECT_NEAR(e.speed_mps, 10.0, 0.3);
}

TEST(EgoCore, KnowsWhenTheRoadEnds) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.start_s_m = sc.road.length_m - sc.window.inner_ahead_m - sc.window.outer_ahead_m - 10.0;
  ego::EgoCore core(sc);
  EXPECT_FALSE(core.at_road_end());
  for (Step k = 1; k <= 20; ++k) core.step(k, {});
  EXPECT_TRUE(core.at_road_end());
}

}  // namespace
}  // namespace entourage
