// The meso core: handoffs at the borders and retirement beyond the window's edges, plans once per
// update period without collisions, passes in the outer regions of a rural road, lane changes
// called off, and meso speeds consistent with the micro model's equilibrium.
#include <gtest/gtest.h>

#include <cmath>

#include "core_test_util.hpp"
#include "meso/core/equilibrium.hpp"
#include "meso/core/meso_core.hpp"
#include "region_core_util.hpp"
#include "road/window.hpp"

namespace entourage {
namespace {

using entourage::testing::as_world;
using entourage::testing::birth;
using entourage::testing::car;
using entourage::testing::ego_at;
using entourage::testing::kMesoId;
using entourage::testing::kMicroId;
using entourage::testing::minimal_scenario;
using entourage::testing::run_step;

TEST(MesoCore, VehiclesEnteringTheInnerRegionGoToMicro) {
  ScenarioConfig sc = minimal_scenario();
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  StepOutput out = run_step(core, 1, ego, {birth(car(sc, 1, 0, w.inner_rear_m - 5.0, 30.0, 30.0), Role::kMeso, Region::kOuterRear)}, {});
  EXPECT_TRUE(out.handoffs.empty());
  out = run_step(core, 2, ego, {}, {});
  ASSERT_EQ(out.handoffs.size(), 1U);
  EXPECT_EQ(out.handoffs[0].to_role, Role::kMicro);
  EXPECT_EQ(out.handoffs[0].to_region, Region::kInner);
  EXPECT_EQ(out.states.size(), 1U);  // still published by meso in that step
}

TEST(MesoCore, VehiclesLeavingAheadGoOnInTheFrontZoneOthersRetire) {
  ScenarioConfig sc = minimal_scenario();
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  const double margin = sc.window.handoff_hysteresis_m;
  Vehicle ahead = car(sc, 1, 0, w.front_edge_m + margin - 5.0, 30.0, 30.0);
  Vehicle oncoming = car(sc, 2, 0, w.rear_edge_m - margin + 5.0, 30.0, 30.0);
  oncoming.direction = Direction::kBackward;
  StepOutput out = run_step(core, 1, ego,
                            {birth(ahead, Role::kMeso, Region::kOuterFront), birth(oncoming, Role::kMeso, Region::kOuterRear)}, {});
  EXPECT_EQ(out.states.size(), 2U);
  out = run_step(core, 2, ego, {}, {});
  ASSERT_EQ(out.handoffs.size(), 2U);
  // the one ahead in the ego's direction: published one last time, then the generator's
  EXPECT_EQ(out.handoffs[0].vehicle.id, 1U);
  EXPECT_EQ(out.handoffs[0].to_role, Role::kGenerator);
  ASSERT_EQ(out.states.size(), 1U);
  EXPECT_EQ(out.states[0].id, 1U);
  // the oncoming one behind the window: retired, no longer published
  EXPECT_EQ(out.handoffs[1].vehicle.id, 2U);
  EXPECT_EQ(out.handoffs[1].to_role, Role::kNone);
  EXPECT_EQ(out.handoffs[1].reason, HandoffReason::kLeftWindow);
}

// A vehicle the director withdraws (a gap it opens in the oncoming traffic) is taken off the road
// at the step its owner gets the command: handed to nobody, no longer published, counted.
TEST(MesoCore, AVehicleWithdrawnByTheDirectorIsTakenOffTheRoad) {
  ScenarioConfig sc = minimal_scenario();
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  Vehicle oncoming = car(sc, 1, 0, w.inner_front_m + 300.0, 25.0, 25.0);
  oncoming.direction = Direction::kBackward;
  Vehicle other = car(sc, 2, 0, w.inner_front_m + 200.0, 25.0, 25.0);
  StepOutput out = run_step(core, 1, ego,
                            {birth(oncoming, Role::kMeso, Region::kOuterFront), birth(other, Role::kMeso, Region::kOuterFront)}, {});
  ASSERT_EQ(out.states.size(), 2U);
  ActorCommand c;
  c.vehicle = 1;
  c.step = 1;
  c.control.mode = ControlMode::kWithdrawn;
  out = run_step(core, 2, ego, {}, as_world(out, kMesoId), {c});
  ASSERT_EQ(out.handoffs.size(), 1U);
  EXPECT_EQ(out.handoffs[0].vehicle.id, 1U);
  EXPECT_EQ(out.handoffs[0].to_role, Role::kNone);
  EXPECT_EQ(out.handoffs[0].reason, HandoffReason::kDirector);
  ASSERT_EQ(out.states.size(), 1U);
  EXPECT_EQ(out.states[0].id, 2U);
  EXPECT_EQ(core.counters().taken_off, 1U);
  EXPECT_EQ(core.counters().retired, 0U);
}

TEST(MesoCore, AFrontOnlyInstanceHandsRearVehiclesOn) {
  ScenarioConfig sc = minimal_scenario();
  meso::MesoCore core(sc, ServiceId{Role::kMeso, kMesoFront});
  // the ego jumped: a vehicle this instance owns now lies in the rear outer region
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  Handoff h = birth(car(sc, 1, 0, w.rear_edge_m + 50.0, 0.0, 30.0), Role::kMeso, Region::kOuterFront);
  const StepOutput out = run_step(core, 1, ego, {h}, {});
  ASSERT_EQ(out.handoffs.size(), 1U);
  EXPECT_EQ(out.handoffs[0].to_role, Role::kMeso);
  EXPECT_EQ(out.handoffs[0].to_region, Region::kOuterRear);
}

TEST(MesoCore, NoVehicleEverPassesItsLeaderInALane) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 1;
  sc.window.outer_ahead_m = 20000.0;
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 0.0, 0.0);
  const WindowBounds w = WindowBounds::around(0.0, sc.window);
  std::vector<Handoff> in;
  in.push_back(birth(car(sc, 1, 0, w.inner_front_m + 400.0, 15.0, 15.0), Role::kMeso, Region::kOuterFront));
  for (VehicleId id = 2; id <= 8; ++id) {
    in.push_back(birth(car(sc, id, 0, w.inner_front_m + 400.0 - 40.0 * id, 35.0, 40.0), Role::kMeso, Region::kOuterFront));
  }
  StepOutput out = run_step(core, 1, ego, in, {});
  for (Step k = 2; k < 1200; ++k) {
    out = run_step(core, k, ego, {}, as_world(out, kMesoId));
    auto v = core.fleet().vehicles();
    std::sort(v.begin(), v.end(), [](const Vehicle& a, const Vehicle& b) { return a.s_m > b.s_m; });
    for (std::size_t i = 1; i < v.size(); ++i) {
      ASSERT_EQ(v[i].id, v[i - 1].id + 1) << "order changed at step " << k;
      ASSERT_GT(v[i - 1].s_m - v[i].s_m, 0.5 * (v[i].length_m + v[i - 1].length_m)) << "overlap at step " << k;
    }
  }
  // the platoon has settled behind the slow leader
  for (const auto& v : core.fleet().vehicles()) EXPECT_NEAR(v.speed_mps, 15.0, 0.5) << v.id;
}

// Meso plans every vehicle once per update period (1 s, 10 steps) and in between moves it along
// its ramp: the acceleration it publishes stays the same from one plan to the next.
TEST(MesoCore, PlansEveryVehicleOncePerPeriodAndMovesItAlongItsRampInBetween) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 1;
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  StepOutput out = run_step(core, 1, ego, {birth(car(sc, 1, 0, w.inner_front_m + 300.0, 20.0, 33.0), Role::kMeso,
                                                 Region::kOuterFront)},
                            {});
  std::vector<double> accel;
  for (Step k = 2; k <= 40; ++k) {
    out = run_step(core, k, ego, {}, as_world(out, kMesoId));
    ASSERT_EQ(out.states.size(), 1U);
    accel.push_back(out.states[0].accel_mps2);
  }
  EXPECT_EQ(core.counters().steps, 40U);
  EXPECT_EQ(core.counters().planning_steps, 4U);  // steps 10, 20, 30 and 40
  EXPECT_EQ(core.counters().plans, 4U);
  // steps 10..19 one ramp, 20..29 the next: the same acceleration within each, a free road's
  for (std::size_t i = 8; i < 18; ++i) EXPECT_DOUBLE_EQ(accel[i], accel[8]) << i;
  EXPECT_GT(accel[8], 0.0);
}

// Two vehicles side by side in the outer lanes of three, both wanting the free middle lane at the
// same plan: the first (in id order) takes it, the other stays.
TEST(MesoCore, TwoVehiclesChoosingTheSameRoomAtOnceDoNotBothTakeIt) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 3;
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  const double s = w.inner_front_m + 300.0;
  // A slow vehicle ahead in the right lane makes vehicle 1 want to pass to the left; vehicle 2 in
  // the left lane, free ahead, wants to keep right. Both look at the middle lane beside them.
  std::vector<Handoff> in{birth(car(sc, 1, 0, s, 30.0, 33.0), Role::kMeso, Region::kOuterFront),
                          birth(car(sc, 2, 2, s, 30.0, 33.0), Role::kMeso, Region::kOuterFront),
                          birth(car(sc, 3, 0, s + 30.0, 15.0, 15.0), Role::kMeso, Region::kOuterFront)};
  StepOutput out = run_step(core, 9, ego, in, {});
  out = run_step(core, 10, ego, {}, as_world(out, kMesoId));  // the plan
  int into_middle = 0;
  for (const Vehicle& v : core.fleet().vehicles()) {
    if (v.lane_change.moving() && v.lane_change.to_lane == 1) ++into_middle;
  }
  EXPECT_EQ(into_middle, 1);
  const Vehicle* first = nullptr;
  for (const Vehicle& v : core.fleet().vehicles()) {
    if (v.id == 1) first = &v;
  }
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(first->lane_change.moving());
}

// A car in the rear outer region behind a vehicle that brakes at 9 m/s^2 to a standstill just after
// a plan. The car notices at the next plan (a second later, a driver's
// reaction), then is alert and planned at every step: it stops behind the leader, never into it.
// Planned only once a second it drove into it (found in a 30-minute rural drive).
TEST(MesoCore, ACarBehindALeaderThatBrakesHardStopsBehindIt) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 1;
  sc.window.outer_behind_m = 1000.0;
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 20.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  const Vehicle follower = car(sc, 1, 0, w.rear_edge_m + 50.0, 20.0, 25.0);
  ObservedVehicle leader;  // another owner's (the world as published)
  leader.id = 2;
  leader.owner = kMicroId;
  leader.s_m = follower.s_m + 45.0;
  leader.speed_mps = 20.0;
  StepOutput out = run_step(core, 10, ego, {birth(follower, Role::kMeso, Region::kOuterRear)}, {leader});
  double min_gap = 1e9;
  for (Step k = 11; k < 120; ++k) {
    const double brake = k > 11 ? 9.0 : 0.0;
    leader.accel_mps2 = leader.speed_mps > 0.0 ? -brake : 0.0;
    leader.speed_mps = std::max(0.0, leader.speed_mps - brake * 0.1);
    leader.s_m += leader.speed_mps * 0.1;
    std::vector<ObservedVehicle> world = as_world(out, kMesoId);
    world.push_back(leader);
    out = run_step(core, k, ego, {}, world);
    ASSERT_EQ(core.fleet().size(), 1U);
    const Vehicle& v = core.fleet().vehicles()[0];
    min_gap = std::min(min_gap, leader.s_m - v.s_m - 0.5 * (v.length_m + leader.length_m));
  }
  EXPECT_GT(min_gap, 0.0);
  EXPECT_NEAR(core.fleet().vehicles()[0].speed_mps, 0.0, 0.01);
  EXPECT_GT(core.counters().alert_plans, 0U);
}

// An actor the director asks to drive faster than its driver wishes (to catch up with its start)
// speeds up in meso as micro's model would, also with a leader far ahead: its own speed-gap
// relation, capped at its own desired speed within a kilometre of any leader, kept a cutter at its
// own 30.9 m/s where it was asked 36.8 for a minute (cut-in seed 136). A vehicle left alone stays
// at its own speed behind the same leader.
TEST(MesoCore, AnActorAskedAboveItsDesiredSpeedSpeedsUpBehindAFarLeader) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 1;
  sc.window.outer_ahead_m = 20000.0;
  const EgoObservation ego = ego_at(0, 3000.0, 0.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  auto speed_after_20_s = [&](bool asked) {
    meso::MesoCore core(sc, kMesoId);
    const Vehicle actor = car(sc, 1, 0, w.inner_front_m + 100.0, 30.0, 30.0);
    const Vehicle leader = car(sc, 2, 0, w.inner_front_m + 500.0, 30.0, 30.0);
    StepOutput out = run_step(core, 1, ego,
                              {birth(actor, Role::kMeso, Region::kOuterFront), birth(leader, Role::kMeso, Region::kOuterFront)},
                              {});
    std::vector<ActorCommand> commands;
    if (asked) {
      ActorCommand c;
      c.vehicle = 1;
      c.step = 1;
      c.control.mode = ControlMode::kTransported;
      c.control.speed_mps = 36.0;
      c.control.lane = 0;
      commands.push_back(c);
    }
    for (Step k = 2; k <= 200; ++k) {
      out = run_step(core, k, ego, {}, as_world(out, kMesoId), k == 2 ? commands : std::vector<ActorCommand>{});
    }
    const Vehicle* v = core.fleet().find(1);
    return v == nullptr ? -1.0 : v->speed_mps;
  };
  EXPECT_GT(speed_after_20_s(true), 34.0);
  EXPECT_LT(speed_after_20_s(false), 30.0 + 1e-9);
}

// A road of one lane each way with oncoming traffic, where drivers that overtake pass in the
// oncoming lane.
ScenarioConfig two_lane_rural() {
  ScenarioConfig sc = minimal_scenario();
  sc.road.kind = RoadKind::kRural;
  sc.road.lanes_forward = 1;
  sc.road.lanes_backward = 1;
  return sc;
}

// Births into `region`: a car that overtakes (id 1) at `s_m`, held up 40 m behind a slow vehicle
// (id 2) that does not change lanes.
std::vector<Handoff> overtaker_behind_slow_vehicle(const ScenarioConfig& sc, double s_m, Region region) {
  Vehicle fast = car(sc, 1, 0, s_m, 22.0, 25.0);
  fast.driver.lane_change = LaneChangeModel::kOvertaking;
  Vehicle slow = car(sc, 2, 0, s_m + 40.0, 16.0, 16.0);
  slow.driver.lane_change = LaneChangeModel::kNone;
  return {birth(fast, Role::kMeso, region), birth(slow, Role::kMeso, region)};
}

// On a two-lane rural road a car that overtakes, held up behind a slow truck in the front outer
// region with the oncoming lane empty, passes it there (driven by micro's model from the start
// of the pass until it is back in its lane) and stays meso's while it passes.
// A rural road with a long outer region ahead, a standing ego, and an overtaker behind a slow
// vehicle 60 m into that region: the first step.
struct PassAhead {
  ScenarioConfig sc = [] {
    ScenarioConfig c = two_lane_rural();
    c.window.outer_ahead_m = 3000.0;
    return c;
  }();
  meso::MesoCore core{sc, kMesoId};
  EgoObservation ego = ego_at(0, 3000.0, 0.0);
  StepOutput out = run_step(
      core, 1, ego,
      overtaker_behind_slow_vehicle(sc, WindowBounds::around(3000.0, sc.window).inner_front_m + 60.0, Region::kOuterFront),
      {});
  void step(Step k) { out = run_step(core, k, ego, {}, as_world(out, kMesoId)); }
};

TEST(MesoCore, ACarPassesASlowTruckInTheOuterRegionOfARuralRoad) {
  PassAhead p;
  bool used_oncoming_lane = false;
  for (Step k = 2; k < 400; ++k) {
    p.step(k);
    ASSERT_EQ(p.core.fleet().size(), 2U) << "step " << k;  // neither left (the window is long enough)
    for (const VehicleReport& r : p.out.states) used_oncoming_lane |= r.id == 1 && r.target_lane == 1;
  }
  const Vehicle& a = p.core.fleet().vehicles()[0];
  const Vehicle& b = p.core.fleet().vehicles()[1];
  EXPECT_TRUE(used_oncoming_lane);
  EXPECT_EQ(p.core.counters().overtakings_started, 1U);
  EXPECT_EQ(a.lane, 0);
  EXPECT_FALSE(a.overtaking.active());
  EXPECT_GT(a.s_m, b.s_m + 10.0);
}

// Back in its lane after the pass, the car is planned at the next step, not at the next update up
// to a second later: it would keep the braking of its return meanwhile (rural_ego_fast, seed 1:
// held 4.2 m/s^2 for 0.7 s, braked at 9 m/s^2 at the next plan, and the car behind it was hit).
TEST(MesoCore, ACarBackFromItsPassIsPlannedAtTheNextStep) {
  PassAhead p;
  bool was_passing = false;
  Step back_at = 0;
  for (Step k = 2; k < 400 && back_at == 0; ++k) {
    p.step(k);
    const bool passing = p.core.fleet().vehicles()[0].overtaking.active();
    if (was_passing && !passing) back_at = k;
    was_passing = passing;
  }
  ASSERT_GT(back_at, 0U) << "the pass never ended";
  const auto steps_per_plan = static_cast<Step>(std::lround(1.0 / p.sc.step_s));
  ASSERT_NE((back_at + 1) % steps_per_plan, 0U) << "the next step is an update anyway: move the start";
  const std::uint64_t before = p.core.counters().alert_plans;
  p.step(back_at + 1);
  EXPECT_EQ(p.core.counters().alert_plans, before + 1);
}

// The same pass begun just behind the inner region: the overtaker crosses into it while it passes,
// stays meso's until it is back in its lane (a handoff does not carry the manoeuvre), and is then
// handed to micro.
TEST(MesoCore, AnOvertakerIsHandedToMicroOnlyWhenBackInItsLane) {
  const ScenarioConfig sc = two_lane_rural();
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 5000.0, 0.0);
  const WindowBounds w = WindowBounds::around(5000.0, sc.window);
  StepOutput out =
      run_step(core, 1, ego, overtaker_behind_slow_vehicle(sc, w.inner_rear_m - 70.0, Region::kOuterRear), {});
  bool passed_inside = false;  // meso's, overtaking, within the inner region
  bool handed_over = false;
  for (Step k = 2; k < 400 && !handed_over; ++k) {
    out = run_step(core, k, ego, {}, as_world(out, kMesoId));
    for (const Handoff& h : out.handoffs) {
      if (h.vehicle.id != 1) continue;
      EXPECT_EQ(h.to_role, Role::kMicro);
      EXPECT_FALSE(h.vehicle.overtaking.active()) << "step " << k;
      EXPECT_EQ(h.vehicle.target_lane(), 0) << "step " << k;
      handed_over = true;
    }
    for (const Vehicle& v : core.fleet().vehicles()) {
      passed_inside |= v.id == 1 && v.overtaking.active() && w.in_inner(v.s_m);
    }
  }
  EXPECT_EQ(core.counters().overtakings_started, 1U);
  EXPECT_TRUE(passed_inside);
  EXPECT_TRUE(handed_over);
}

// A vehicle that has just begun to change lanes, and one placed in its target lane in that same
// step, close ahead (a birth at the window's edge, decided without knowing of the change). Found
// in a 30-minute drive: the changer braked at 39 m/s^2, its peers refused that sample, so the
// generator did not see it and placed the next vehicle on top of it.
struct CallOffCase {
  StepOutput out;
  Vehicle changer;
  std::uint64_t called_off = 0;
};

CallOffCase change_into_a_birth(double elapsed_s, bool with_birth) {
  ScenarioConfig sc = minimal_scenario();
  sc.road.lanes_forward = 2;
  meso::MesoCore core(sc, kMesoId);
  const EgoObservation ego = ego_at(0, 3000.0, 28.0);
  const WindowBounds w = WindowBounds::around(3000.0, sc.window);
  Vehicle changer = car(sc, 1, 1, w.rear_edge_m + 20.0, 24.7, 33.0);
  changer.lane_change.from_lane = 1;
  changer.lane_change.to_lane = 0;
  changer.lane_change.phase = LaneChangePhase::kMoving;
  changer.lane_change.phase_elapsed_s = elapsed_s;
  changer.lane_change.duration_s = 4.0;
  std::vector<Handoff> in{birth(changer, Role::kMeso, Region::kOuterRear)};
  if (with_birth) in.push_back(birth(car(sc, 2, 0, changer.s_m + 2.8, 30.8, 33.0), Role::kMeso, Region::kOuterRear));
  CallOffCase c;
  c.out = run_step(core, 1, ego, in, {});
  for (const Vehicle& v : core.fleet().vehicles()) {
    if (v.id == 1) c.changer = v;
  }
  c.called_off = core.counters().called_off_lane_changes;
  return c;
}

TEST(MesoCore, AChangeJustBegunIsCalledOffWhenItsTargetLaneFillsUp) {
  const CallOffCase c = change_into_a_birth(0.1, true);
  EXPECT_EQ(c.called_off, 1U);
  EXPECT_FALSE(c.changer.lane_change.active());
  EXPECT_EQ(c.changer.lane, 1);
  // it drives on in its own lane instead of braking for the vehicle beside it
  EXPECT_GT(c.changer.accel_mps2, -c.changer.driver.car_following.idm.comfort_decel_mps2);
}

TEST(MesoCore, AChangeUnderWayOrWithRoomGoesOn) {
  const CallOffCase under_way = change_into_a_birth(1.5, true);  // 35 % of the way sideways
  EXPECT_EQ(under_way.called_off, 0U);
  EXPECT_TRUE(under_way.changer.lane_change.moving());
  const CallOffCase room = change_into_a_birth(0.1, false);
  EXPECT_EQ(room.called_off, 0U);
  EXPECT_TRUE(room.changer.lane_change.moving());
  EXPECT_EQ(room.changer.lane_change.to_lane, 0);
}

TEST(MesoEquilibrium, MatchesTheModelsEquilibriumGap) {
  CarFollowingParams p;
  p.idm.desired_speed_mps = 33.0;
  const meso::EquilibriumSpeed eq(p);
  for (double v : {0.5, 5.0, 15.0, 25.0, 32.0}) {
    const double gap = idm_equilibrium_gap_m(p.idm, v);
    if (gap > eq.max_gap_m()) continue;
    EXPECT_NEAR(eq.at(gap), v, 0.25) << "v " << v;
  }
  EXPECT_DOUBLE_EQ(eq.at(1e9), 33.0);
  EXPECT_LT(eq.at(0.0), 0.1);
}

}  // namespace
}  // namespace entourage
