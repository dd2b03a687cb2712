// The figures `entourage verify` computes from a recording besides the invariants: the catch-up
// prediction, the flow's standard error, the micro-meso transitions as driven.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core_test_util.hpp"
#include "recording/summary.hpp"
#include "recording/tables.hpp"
#include "recording/transitions.hpp"
#include "traffic/observed_stream.hpp"
#include "traffic/road_sim.hpp"

// The catch-up prediction for a recording: a standing ego is passed by the whole flow and passes
// nobody; oncoming, it meets the whole oncoming flow. At the stream's mean speed it overtakes and is
// overtaken alike within the spread of speeds.
namespace entourage::recording {
namespace {

Tables ego_driving(double speed_mps, int steps) {
  Tables t;
  for (int k = 0; k < steps; ++k) {
    EgoRow e;
    e.step = static_cast<std::uint64_t>(k);
    e.speed_mps = speed_mps;
    t.ego.push_back(e);
  }
  return t;
}

TEST(PastTheEgoPrediction, AStandingEgoIsPassedByTheWholeFlow) {
  const ScenarioConfig sc = entourage::testing::freeway_scenario();
  const double seconds = 600.0;
  const auto p = predict_past_ego(ego_driving(0.0, static_cast<int>(seconds / sc.step_s)), sc);
  EXPECT_NEAR(p.overtaking, sc.forward.flow_veh_per_s * seconds, 1e-6 * sc.forward.flow_veh_per_s * seconds + 1.0);
  EXPECT_EQ(p.overtaken, 0.0);
  EXPECT_NEAR(p.met, sc.backward.flow_veh_per_s * seconds, 0.01 * sc.backward.flow_veh_per_s * seconds);
}

TEST(PastTheEgoPrediction, UsesTheStreamTheRunsGeneratorObserved) {
  // The run's seed is in the recording; the prediction observes with the generator's seeds.
  const ScenarioConfig sc = entourage::testing::freeway_scenario();
  const int steps = 6000;
  const double u = 25.0;
  Tables t = ego_driving(u, steps);
  t.info.seed = 7;
  const auto p = predict_past_ego(t, sc);
  const std::uint64_t seed = generator_seed(7);
  const ObservedStream forward(sc, Direction::kForward, StreamObservation{}, observation_seed(seed, Direction::kForward));
  const ObservedStream backward(sc, Direction::kBackward, StreamObservation{},
                                observation_seed(seed, Direction::kBackward));
  const double seconds = steps * sc.step_s;
  EXPECT_NEAR(p.overtaking, forward.vehicles_rear_per_s(u) * seconds, 1e-6 * p.overtaking);
  EXPECT_NEAR(p.overtaken, forward.vehicles_front_per_s(u) * seconds, 1e-6 * p.overtaken);
  EXPECT_NEAR(p.met, backward.vehicles_oncoming_per_s(u) * seconds, 1e-6 * p.met);
}

// The relations are those of the stream on the reference road (straight, no zones): where the
// window reaches a speed zone (or a curve, an overtaking restriction, a closure) a catch-up is
// counted as a catch-up but not against the prediction, and the prediction skips those steps too.
TEST(PastTheEgoPrediction, CountsOnlyWhereTheWindowIsOnAStretchLikeTheReferenceRoad) {
  ScenarioConfig sc = entourage::testing::freeway_scenario();
  sc.road.speed_zones.push_back({5000.0, 5500.0, 22.0});
  const auto drive_at = [&](double ego_s_m) {
    Tables t = ego_driving(25.0, 2);
    for (EgoRow& e : t.ego) e.s_m = ego_s_m;
    for (std::uint64_t step : {0u, 1u}) {  // a vehicle passes the ego between the steps
      VehicleRow r;
      r.step = step;
      r.id = 7;
      r.region = "inner";
      r.s_m = ego_s_m + (step == 0 ? -1.0 : 1.0);
      t.vehicles.push_back(r);
    }
    return t;
  };
  const Tables far = drive_at(1000.0);  // the window reaches 1000 m ahead at most
  const Tables near = drive_at(4500.0);
  EXPECT_EQ(measure_past_ego(far, sc).overtaking_counted, 1u);
  EXPECT_DOUBLE_EQ(measure_past_ego(far, sc).counted_share, 1.0);
  EXPECT_GT(predict_past_ego(far, sc).overtaking, 0.0);
  EXPECT_EQ(measure_past_ego(near, sc).overtaking, 1u);
  EXPECT_EQ(measure_past_ego(near, sc).overtaking_counted, 0u);
  EXPECT_DOUBLE_EQ(measure_past_ego(near, sc).counted_share, 0.0);
  EXPECT_EQ(predict_past_ego(near, sc).overtaking, 0.0);
}

TEST(LikeReferenceRoad, OnlyAStraightStretchWithoutZonesRestrictionsOrClosures) {
  RoadConfig road;
  road.segments = {{1000.0, 0.0}, {500.0, 0.002}, {1000.0, 0.0}};
  road.speed_zones.push_back({4000.0, 4500.0, 20.0});
  road.no_overtaking.push_back({6000.0, 6500.0});
  road.lane_closures.push_back({Direction::kForward, 0, 8000.0, 8500.0});
  EXPECT_TRUE(like_reference_road(road, 0.0, 900.0));
  EXPECT_FALSE(like_reference_road(road, 900.0, 1100.0));   // into the curve
  EXPECT_TRUE(like_reference_road(road, 1600.0, 3900.0));   // past it, beyond the last segment too
  EXPECT_FALSE(like_reference_road(road, 4400.0, 5000.0));  // the speed zone
  EXPECT_FALSE(like_reference_road(road, 5500.0, 6100.0));  // the overtaking restriction
  EXPECT_FALSE(like_reference_road(road, 8400.0, 9000.0));  // the closure
  EXPECT_TRUE(like_reference_road(road, 8600.0, 9600.0));
}

TEST(PastTheEgoPrediction, FasterEgosOvertakeMoreAndAreOvertakenLess) {
  const ScenarioConfig sc = entourage::testing::freeway_scenario();
  const auto slow = predict_past_ego(ego_driving(25.0, 6000), sc);
  const auto fast = predict_past_ego(ego_driving(35.0, 6000), sc);
  EXPECT_GT(slow.overtaking, fast.overtaking);
  EXPECT_LT(slow.overtaken, fast.overtaken);
  EXPECT_LT(slow.met, fast.met);
}

}  // namespace
}  // namespace entourage::recording

// The flow's standard error: vehicles arriving evenly give the compound-count estimate (each
// vehicle crossing every detector once, n vehicles: the flow over sqrt(n)); the same vehicles
// bunched into the first third of the drive give the batch means' larger one.
namespace entourage::recording {
namespace {

constexpr double kEgo_m = 5000.0;
constexpr double kSpeed_mps = 30.0;
constexpr int kSteps = 6000;
constexpr int kVehicles = 20;

Tables standing_ego_passed_by(int entry_every_steps) {
  const ScenarioConfig sc = entourage::testing::freeway_scenario();
  Tables t = ego_driving(0.0, kSteps);
  for (auto& e : t.ego) e.s_m = kEgo_m;
  const double from = kEgo_m - sc.window.inner_behind_m - sc.window.outer_behind_m - 20.0;
  const double to = kEgo_m + sc.window.inner_ahead_m + sc.window.outer_ahead_m + 20.0;
  for (int i = 0; i < kVehicles; ++i) {
    const int entry = i * entry_every_steps;
    for (int k = entry; k < kSteps; ++k) {
      VehicleRow r;
      r.step = static_cast<std::uint64_t>(k);
      r.id = static_cast<std::uint32_t>(i + 1);
      r.s_m = from + kSpeed_mps * sc.step_s * (k - entry);
      if (r.s_m > to) break;
      r.speed_mps = kSpeed_mps;
      t.vehicles.push_back(r);
    }
  }
  std::stable_sort(t.vehicles.begin(), t.vehicles.end(),
                   [](const VehicleRow& a, const VehicleRow& b) { return a.step < b.step; });
  return t;
}

TEST(FlowError, EvenArrivalsGiveTheCompoundCountError) {
  const ScenarioConfig sc = entourage::testing::freeway_scenario();
  const FlowMeasurement f = measure_flow(standing_ego_passed_by(250), sc, 1, 25.0);
  const double drive_h = kSteps * sc.step_s / 3600.0;
  EXPECT_NEAR(f.measured_veh_per_h, kVehicles / drive_h, 1.0);
  EXPECT_NEAR(f.standard_error_veh_per_h, f.measured_veh_per_h / std::sqrt(kVehicles), 1.0);
  EXPECT_EQ(f.vehicles, static_cast<std::uint64_t>(kVehicles));
}

TEST(FlowError, BunchedArrivalsGiveTheBatchMeansLargerError) {
  const ScenarioConfig sc = entourage::testing::freeway_scenario();
  const FlowMeasurement even = measure_flow(standing_ego_passed_by(250), sc, 1, 25.0);
  const FlowMeasurement bunched = measure_flow(standing_ego_passed_by(60), sc, 1, 25.0);
  EXPECT_NEAR(bunched.measured_veh_per_h, even.measured_veh_per_h, 1.0);
  EXPECT_GT(bunched.standard_error_veh_per_h, 1.3 * even.standard_error_veh_per_h);
}

// --- Transitions between micro and meso

// Rows of vehicle `id` from `first` to `last` step: owned by `owner`, in `lane`, at `speed_mps`
// and `accel_mps2` (positions do not matter here).
void drive(Tables& t, std::uint32_t id, std::uint64_t first, std::uint64_t last, const char* owner, int lane,
           double speed_mps, double accel_mps2, const char* control = "autonomous") {
  for (std::uint64_t k = first; k <= last; ++k) {
    VehicleRow r{k, 0.1 * k, id, owner, "inner", 1, lane, lane, 1000.0, 0, 0, 0, 0, speed_mps, accel_mps2, 4.5, 1.8, "car"};
    r.control = control;
    t.vehicles.push_back(r);
  }
}

HandoffRow border(std::uint64_t step, std::uint32_t id, const char* from, const char* to_role) {
  return {step, 0.1 * step, id, 2, from, to_role, "inner", "border", 0, 1000.0, 30.0};
}

// A run's summary counts what left the road: retired beyond the window's edges and, apart, what the
// director took off out of sight (a gap in the oncoming traffic).
TEST(RunSummary, CountsTheVehiclesTheDirectorTookOffApart) {
  Tables t = ego_driving(20.0, 10);
  auto handoff = [](std::uint32_t id, const char* from, const char* to_role, const char* reason) {
    HandoffRow h;
    h.step = 5;
    h.vehicle_id = id;
    h.from = from;
    h.to_role = to_role;
    h.reason = reason;
    return h;
  };
  t.handoffs = {handoff(1, "generator", "meso", "birth"), handoff(1, "meso", "none", "left_window"),
                handoff(2, "meso", "none", "director"), handoff(3, "meso", "micro", "border")};
  sort_rows(t);
  const RunSummary s = summarize(t, testing::minimal_scenario(), 500.0);
  EXPECT_EQ(s.generated, 1U);
  EXPECT_EQ(s.removed, 2U);
  EXPECT_EQ(s.taken_off, 1U);
  EXPECT_EQ(s.transfers, 1U);
}

TEST(Transitions, AVehicleIntoMicroCountsItsHardestBrakingOverItsFirstThreeSecondsThere) {
  Tables t;
  // Vehicle 1: handed to micro at step 10; it brakes at 1, 4, then 2 m/s^2, and at 8 m/s^2 only
  // after its first 3 s (30 steps) in micro: 4 counts.
  drive(t, 1, 0, 10, "meso", 0, 30.0, 0.0);
  drive(t, 1, 11, 12, "micro", 0, 30.0, -1.0);
  drive(t, 1, 13, 13, "micro", 0, 30.0, -4.0);
  drive(t, 1, 14, 40, "micro", 0, 30.0, -2.0);
  drive(t, 1, 41, 45, "micro", 0, 30.0, -8.0);
  // Vehicle 2: calm. Vehicle 3: under the director's command (a script may brake it): left out.
  drive(t, 2, 0, 10, "meso", 0, 30.0, 0.0);
  drive(t, 2, 11, 20, "micro", 0, 30.0, -0.5);
  drive(t, 3, 0, 10, "meso", 0, 30.0, 0.0);
  drive(t, 3, 11, 20, "micro", 0, 30.0, -9.0, "controlled");
  t.handoffs = {border(10, 1, "meso", "micro"), border(10, 2, "meso-front", "micro"), border(10, 3, "meso", "micro")};
  sort_rows(t);
  const IntoMicro m = measure_transitions(t, 0.1).into_micro;
  EXPECT_EQ(m.handoffs, 2U);
  EXPECT_DOUBLE_EQ(m.max_decel_mps2, 4.0);
  EXPECT_DOUBLE_EQ(m.median_decel_mps2, 0.5);
  EXPECT_EQ(m.hard, 1U);
}

TEST(Transitions, AVehicleIntoMesoKeepsItsLaneAndSpeed) {
  Tables t;
  // Vehicle 1: micro's last row at 30 m/s accelerating at 1 m/s^2, meso's first at 30.1 m/s in
  // the same lane: no jump. Vehicle 2: moving from lane 0 to lane 1 in micro, in lane 1 in meso,
  // 2 m/s slower than micro left it: the lane is kept, the speed jumps.
  drive(t, 1, 0, 10, "micro", 0, 30.0, 1.0);
  drive(t, 1, 11, 15, "meso", 0, 30.1, 0.0);
  drive(t, 2, 0, 10, "micro", 0, 25.0, 0.0);
  for (VehicleRow& r : t.vehicles) {
    if (r.id == 2) r.target_lane = 1;
  }
  drive(t, 2, 11, 15, "meso-rear", 1, 23.0, 0.0);
  // Vehicle 3 goes to micro, not meso: not counted here.
  drive(t, 3, 0, 10, "micro", 0, 25.0, 0.0);
  t.handoffs = {border(10, 1, "micro", "meso"), border(10, 2, "micro", "meso"), border(10, 3, "meso", "micro")};
  sort_rows(t);
  const IntoMeso m = measure_transitions(t, 0.1).into_meso;
  EXPECT_EQ(m.handoffs, 2U);
  EXPECT_EQ(m.lane_kept, 2U);
  EXPECT_NEAR(m.max_speed_jump_mps, 2.0, 1e-9);
  EXPECT_NEAR(m.mean_speed_jump_mps, 1.0, 1e-9);
}

}  // namespace
}  // namespace entourage::recording
