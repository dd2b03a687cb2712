// The micro core: car following without collisions (the ego a leader like any other, unless
// transparent) and handoffs to meso beyond the inner region's borders.
#include <gtest/gtest.h>

#include "core_test_util.hpp"
#include "micro/core/micro_core.hpp"
#include "region_core_util.hpp"
#include "road/window.hpp"

namespace entourage {
namespace {

using entourage::testing::birth;
using entourage::testing::car;
using entourage::testing::ego_at;
using entourage::testing::minimal_scenario;
using entourage::testing::run_step;

TEST(MicroCore, AQueueBehindAStoppedCarStopsWithoutCollision) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 1;
  sc.window.inner_ahead_m = 5000.0;
  micro::MicroCore core(sc);
  std::vector<Handoff> in;
  Vehicle stopped = car(sc, 1, 0, 2000.0, 0.0, 30.0);
  stopped.driver.car_following.idm.desired_speed_mps = 0.01;  // will not move
  in.push_back(birth(stopped, Role::kMicro, Region::kInner));
  for (VehicleId id = 2; id <= 6; ++id) in.push_back(birth(car(sc, id, 0, 2000.0 - 60.0 * id, 30.0, 33.0), Role::kMicro, Region::kInner));
  const EgoObservation ego = ego_at(0, 1500.0, 0.0);
  StepOutput out = run_step(core, 1, ego, in, {});
  for (Step k = 2; k < 600; ++k) out = run_step(core, k, ego, {}, {});
  ASSERT_EQ(core.fleet().size(), 6U);
  const auto& v = core.fleet().vehicles();
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double gap = v[i - 1].s_m - v[i].s_m - 0.5 * (v[i - 1].length_m + v[i].length_m);
    EXPECT_GT(gap, 1.0) << "between " << v[i].id << " and " << v[i - 1].id;
    EXPECT_LT(v[i].speed_mps, 0.1);
  }
}

TEST(MicroCore, TheEgoIsALeaderLikeAnyOther) {
  ScenarioConfig sc = minimal_scenario();
  micro::MicroCore core(sc);
  // a car 100 m behind a standing ego in its lane: it brakes, changes lane and passes beside the
  // ego, never through it
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  run_step(core, 1, ego, {birth(car(sc, 1, 0, 2900.0, 25.0, 30.0), Role::kMicro, Region::kInner)}, {});
  bool braked = false;
  bool passed = false;
  for (Step k = 2; k < 300; ++k) {
    run_step(core, k, ego, {}, {});
    if (core.fleet().size() == 0) break;
    const Vehicle& v = core.fleet().vehicles().front();
    const bool in_ego_lane = v.lane == 0 || v.target_lane() == 0;
    EXPECT_FALSE(in_ego_lane && std::abs(v.s_m - 3000.0) < 0.5 * (4.5 + 4.6)) << "through the ego at step " << k;
    braked = braked || v.accel_mps2 < -1.0;
    passed = passed || v.s_m > 3010.0;
  }
  EXPECT_TRUE(braked);
  EXPECT_TRUE(passed);
}

// A transparent ego (scenario ego.transparent, a probe for validating the window) is no leader:
// the car of TheEgoIsALeaderLikeAnyOther drives through its place without braking. (Meso's
// vehicles never come that close to the ego: they see it through the same step input.)
TEST(MicroCore, ATransparentEgoIsNobodysLeader) {
  ScenarioConfig sc = minimal_scenario();
  sc.ego.transparent = true;
  micro::MicroCore core(sc);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  run_step(core, 1, ego, {birth(car(sc, 1, 0, 2900.0, 25.0, 25.0), Role::kMicro, Region::kInner)}, {});
  double slowest_mps = 25.0;
  bool through = false;
  for (Step k = 2; k < 100 && core.fleet().size() > 0; ++k) {
    run_step(core, k, ego, {}, {});
    const Vehicle& v = core.fleet().vehicles().front();
    slowest_mps = std::min(slowest_mps, v.speed_mps);
    through = through || (v.lane == 0 && std::abs(v.s_m - ego.s_m) < 1.0);
  }
  EXPECT_TRUE(through) << "the car never reached the ego's place in its lane";
  EXPECT_GT(slowest_mps, 24.0);
}

TEST(MicroCore, HandsVehiclesToMesoBeyondTheBorderPlusHysteresis) {
  ScenarioConfig sc = minimal_scenario();
  micro::MicroCore core(sc);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  // 1 m before the front border, driving away at 30 m/s
  StepOutput out = run_step(core, 1, ego, {birth(car(sc, 1, 0, w.inner_front_m - 1.0, 30.0, 30.0), Role::kMicro, Region::kInner)}, {});
  EXPECT_TRUE(out.handoffs.empty());
  Step k = 2;
  while (out.handoffs.empty() && k < 100) out = run_step(core, k++, ego, {}, {});
  ASSERT_EQ(out.handoffs.size(), 1U);
  const Handoff& h = out.handoffs[0];
  EXPECT_EQ(h.to_role, Role::kMeso);
  EXPECT_EQ(h.to_region, Region::kOuterFront);
  EXPECT_GT(h.vehicle.s_m, w.inner_front_m + sc.window.handoff_hysteresis_m);
  EXPECT_EQ(h.vehicle.handoff_sequence, 2U);
  // published one last time by micro in the step it leaves, then gone
  ASSERT_EQ(out.states.size(), 1U);
  EXPECT_EQ(out.states[0].region, Region::kOuterFront);
  EXPECT_EQ(core.fleet().size(), 0U);
}

}  // namespace
}  // namespace entourage
