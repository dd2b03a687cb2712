#include "roadsim/core/road_experiment.hpp"

#include <algorithm>
#include <cmath>

#include "behaviour/model_registry.hpp"
#include "core/units.hpp"

namespace entourage::roadsim {

namespace {
// Default detector: three quarters along the road, where the stream has settled.
constexpr double kDefaultDetectorShare = 0.75;

std::string apply_driver_overrides(ScenarioConfig& sc, const ExperimentConfig& c) {
  if (!c.car_following.empty() && !car_following_model_by_name(c.car_following)) {
    return "unknown car-following model \"" + c.car_following + "\" (see `entourage models`)";
  }
  if (!c.lane_change.empty() && !lane_change_model_by_name(c.lane_change)) {
    return "unknown lane-change model \"" + c.lane_change + "\" (see `entourage models`)";
  }
  for (VehicleTypeConfig& t : sc.vehicle_types) {
    if (!c.car_following.empty()) t.driver.car_following = c.car_following;
    if (!c.lane_change.empty()) t.driver.lane_change = c.lane_change;
    if (c.human_driver >= 0) t.driver.human_driver = c.human_driver > 0;
    if (t.driver.human_driver && t.driver.car_following == "gipps") {
      return "the Human Driver Model wraps idm or modified_idm, not gipps";
    }
  }
  return {};
}
}  // namespace

Prepared prepare(const ScenarioConfig& scenario, const ExperimentConfig& c) {
  Prepared p;
  p.scenario = scenario;
  ScenarioConfig& sc = p.scenario;
  p.error = apply_driver_overrides(sc, c);
  if (!p.ok()) return p;
  if (c.forward_flow_veh_per_h >= 0.0) sc.forward.flow_veh_per_s = c.forward_flow_veh_per_h / kSecondsPerHour;
  if (c.backward_flow_veh_per_h >= 0.0) sc.backward.flow_veh_per_s = c.backward_flow_veh_per_h / kSecondsPerHour;
  if (c.lanes > 0) {
    sc.road.lanes_forward = c.lanes;
    sc.road.lanes_backward = sc.road.kind == RoadKind::kRural ? c.lanes : std::min(sc.road.lanes_backward, c.lanes);
  }
  if (c.duration_s <= 0.0 || c.warmup_s < 0.0 || c.warmup_s >= c.duration_s) {
    p.error = "the warm-up must be shorter than the duration, both positive";
    return p;
  }
  if (c.interval_s <= 0.0) {
    p.error = "the detector interval must be positive";
    return p;
  }
  RoadSimConfig& r = p.road;
  if (c.decision_interval_s >= 0.0) r.rules.decision_interval_s = c.decision_interval_s;
  r.scenario_road = c.scenario_road;
  r.length_m = c.scenario_road ? sc.road.length_m : c.length_m;
  if (!(r.length_m > 0.0)) {
    p.error = "the road length must be positive";
    return p;
  }
  r.forward = sc.forward.flow_veh_per_s > 0.0;
  r.backward = sc.backward.flow_veh_per_s > 0.0 && sc.road.lanes_backward > 0;
  r.detectors_m = c.detectors_m;
  if (r.detectors_m.empty()) {
    // Three quarters along each simulated direction of travel.
    if (r.backward) r.detectors_m.push_back((1.0 - kDefaultDetectorShare) * r.length_m);
    if (r.forward) r.detectors_m.push_back(kDefaultDetectorShare * r.length_m);
  }
  for (double x : r.detectors_m) {
    if (x <= 0.0 || x >= r.length_m) {
      p.error = "detector at " + std::to_string(x) + " m is not on the road (0 to " + std::to_string(r.length_m) + " m)";
      return p;
    }
  }
  if (!r.forward && !r.backward) p.error = "there is no demand to simulate";
  return p;
}

ExperimentResult run_experiment(const Prepared& prepared, const ExperimentConfig& c,
                                void (*progress)(double time_s, const RoadSim& sim)) {
  ExperimentResult out;
  RoadSim sim(prepared.scenario, prepared.road, c.seed);
  const double dt = prepared.scenario.step_s;
  const auto steps = static_cast<std::uint64_t>(std::llround(c.duration_s / dt));
  const auto warm = static_cast<std::uint64_t>(std::llround(c.warmup_s / dt));
  const auto minute = static_cast<std::uint64_t>(std::llround(60.0 / dt));
  double speed_sum = 0.0;
  std::uint64_t speed_samples = 0;
  for (std::uint64_t k = 1; k <= steps; ++k) {
    sim.step();
    out.max_queue = std::max(out.max_queue, sim.queued());
    if (k > warm) {
      for (const Vehicle& v : sim.fleet().vehicles()) speed_sum += v.speed_mps;
      speed_samples += sim.fleet().size();
    }
    if (progress != nullptr && k % minute == 0) progress(sim.time_s(), sim);
  }
  out.steps = steps;
  out.vehicle_updates = sim.vehicle_updates();
  out.counters = sim.counters();
  out.mean_trip_speed_mps = out.counters.mean_trip_speed_mps();
  out.mean_speed_mps = speed_samples > 0 ? speed_sum / static_cast<double>(speed_samples) : 0.0;
  for (std::size_t d = 0; d < prepared.road.detectors_m.size(); ++d) {
    for (Direction dir : {Direction::kForward, Direction::kBackward}) {
      if ((dir == Direction::kForward && !prepared.road.forward) || (dir == Direction::kBackward && !prepared.road.backward)) {
        continue;
      }
      auto iv = aggregate_crossings(sim.crossings(d), prepared.road.detectors_m[d], dir,
                                    prepared.scenario.road.lanes(dir), c.warmup_s, c.duration_s, c.interval_s);
      out.intervals.insert(out.intervals.end(), iv.begin(), iv.end());
    }
  }
  return out;
}

double max_sustained_flow_per_lane(const std::vector<DetectorInterval>& intervals, Direction dir, double detector_m,
                                   int window) {
  std::vector<double> flows;
  for (const auto& i : intervals) {
    if (i.direction == dir && i.detector_m == detector_m) flows.push_back(i.flow_per_lane_veh_per_h());
  }
  const auto w = static_cast<std::size_t>(std::max(1, window));
  double best = 0.0;
  for (std::size_t i = 0; i + w <= flows.size(); ++i) {
    double sum = 0.0;
    for (std::size_t j = i; j < i + w; ++j) sum += flows[j];
    best = std::max(best, sum / static_cast<double>(w));
  }
  return best;
}

}  // namespace entourage::roadsim
