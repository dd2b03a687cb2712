#include "window_catchups.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "core/units.hpp"
#include "traffic/road_sim.hpp"
#include "window_cores.hpp"

namespace entourage::bench {

ScenarioConfig with_probe(ScenarioConfig sc, double speed_kph) {
  sc.ego.transparent = true;
  sc.ego.driver.use_speed_profile = true;
  sc.ego.driver.profile = {{0.0, kph_to_mps(speed_kph)}};
  sc.ego.start_speed_mps = kph_to_mps(speed_kph);
  sc.ego.driver.lane_changes = false;
  return sc;
}

WindowBounds relative_window(const WindowConfig& w) { return WindowBounds::around(0.0, w); }
double window_length_m(const WindowConfig& w) {
  const WindowBounds b = relative_window(w);
  return b.front_edge_m - b.rear_edge_m;
}
bool in_window(double rel_m, const WindowBounds& b) { return rel_m >= b.rear_edge_m && rel_m < b.front_edge_m; }

void observe_step(Tally& t, double speed_mps, const ObservedStream& stream, double dt, bool counted) {
  const double u = std::max(0.0, speed_mps);
  if (counted) {
    t.predicted_passive += stream.vehicles_rear_per_s(u) * dt;
    t.predicted_active += stream.vehicles_front_per_s(u) * dt;
    t.counted_s += dt;
  }
  t.observed_s += dt;
  t.distance_m += u * dt;
}

void observe_in_window(Tally& t, double before_m, double rel_m, double speed_mps, const WindowBounds& w, double dt) {
  if (in_window(rel_m, w)) {
    t.vehicle_seconds += dt;
    t.vehicle_metres += speed_mps * dt;
    if (rel_m < w.inner_rear_m) {
      t.rear_outer_seconds += dt;
      t.rear_outer_metres += speed_mps * dt;
    }
    if (rel_m >= w.inner_front_m) {
      t.front_outer_seconds += dt;
      t.front_outer_metres += speed_mps * dt;
    }
  }
  if (std::isnan(before_m)) {  // born: in at the nearer edge if inside
    if (in_window(rel_m, w)) (rel_m < 0.0 ? t.rear_in : t.front_in) += 1.0;
    return;
  }
  const double rear = w.rear_edge_m;
  const double front = w.front_edge_m;
  if (before_m < rear && rel_m >= rear) t.rear_in += 1.0;
  if (before_m >= rear && rel_m < rear) t.rear_out += 1.0;
  if (before_m >= front && rel_m < front) t.front_in += 1.0;
  if (before_m < front && rel_m >= front) t.front_out += 1.0;
}

void observe_gone(Tally& t, double before_m, const WindowBounds& w) {
  if (in_window(before_m, w)) (before_m < 0.0 ? t.rear_out : t.front_out) += 1.0;
}

Tally window_drive(const ScenarioConfig& sc, std::uint64_t seed, double duration_s) {
  Tally t;
  bench::WindowCores cores(sc, seed);
  const ObservedStream stream(sc, Direction::kForward, StreamObservation{},
                              observation_seed(generator_seed(seed), Direction::kForward));
  const ObservedStream oncoming(sc, Direction::kBackward, StreamObservation{},
                                observation_seed(generator_seed(seed), Direction::kBackward));
  const WindowBounds w = relative_window(sc.window);
  std::unordered_map<VehicleId, double> before;
  std::unordered_map<VehicleId, double> now;
  std::unordered_set<VehicleId> forward;  // ids of the ego's direction (a gone vehicle's too)
  const auto steps = static_cast<Step>(duration_s / sc.step_s);
  for (Step k = 0; k <= steps && !cores.at_road_end(); ++k) {
    StepInput in = cores.next_input();
    const bench::StepOutputs out = cores.compute(in);
    cores.publish(in, out);
    now.clear();
    for (const ObservedVehicle& v : cores.world()) {
      now[v.id] = v.s_m - in.ego.s_m;
      if (v.direction == Direction::kForward) forward.insert(v.id);
    }
    if (k >= kFillSteps) {
      const bool counted = window_like_reference_road(sc, in.ego.s_m);
      observe_step(t, in.ego.speed_mps, stream, sc.step_s, counted);
      if (counted) t.predicted_met += oncoming.vehicles_oncoming_per_s(std::max(0.0, in.ego.speed_mps)) * sc.step_s;
      for (const ObservedVehicle& v : cores.world()) {
        const auto b = before.find(v.id);
        const bool was = b != before.end();
        const double rel = now[v.id];
        if (v.direction == Direction::kBackward) {
          if (counted && was && b->second >= 0.0 && rel < 0.0) t.met += 1.0;
          if (in_window(rel, w)) t.oncoming_metres += v.speed_mps * sc.step_s;
          continue;
        }
        if (counted && was && b->second < 0.0 && rel >= 0.0) t.passive += 1.0;
        if (counted && was && b->second >= 0.0 && rel < 0.0) t.active += 1.0;
        observe_in_window(t, was ? b->second : std::nan(""), rel, v.speed_mps, w, sc.step_s);
      }
      for (const auto& [id, rel] : before) {
        if (!now.count(id) && forward.count(id)) observe_gone(t, rel, w);
      }
    }
    std::swap(before, now);
  }
  return t;
}

}  // namespace entourage::bench
