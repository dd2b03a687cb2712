#include "recording/summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/units.hpp"
#include "road/window.hpp"
#include "traffic/handoff.hpp"
#include "traffic/headways.hpp"
#include "traffic/observed_stream.hpp"
#include "traffic/road_sim.hpp"

namespace entourage::recording {

double FlowMeasurement::relative_error() const {
  return demand_veh_per_h > 0.0 ? (measured_veh_per_h - demand_veh_per_h) / demand_veh_per_h : 0.0;
}

double FlowMeasurement::relative_standard_error() const {
  return demand_veh_per_h > 0.0 ? standard_error_veh_per_h / demand_veh_per_h : 0.0;
}

double FlowMeasurement::share_below() const {
  return headways > 0 ? static_cast<double>(headways_below) / static_cast<double>(headways) : 0.0;
}

double FlowMeasurement::platoon_size(double share_below) {
  return share_below < 1.0 ? 1.0 / (1.0 - share_below) : std::numeric_limits<double>::infinity();
}

namespace {
// The standard error of a rate from batches of counts over observation times: the spread of the
// batches' rates (those observed at all) over the root of their number.
double batch_means_error(const std::vector<double>& counts, const std::vector<double>& observed_s) {
  std::vector<double> rates;
  for (std::size_t b = 0; b < counts.size(); ++b) {
    if (observed_s[b] > 0.0) rates.push_back(counts[b] / observed_s[b]);
  }
  if (rates.size() < 2) return 0.0;
  double mean = 0.0;
  for (double r : rates) mean += r;
  mean /= static_cast<double>(rates.size());
  double var = 0.0;
  for (double r : rates) var += (r - mean) * (r - mean);
  var /= static_cast<double>(rates.size() - 1);
  return std::sqrt(var / static_cast<double>(rates.size()));
}
}  // namespace

FlowMeasurement measure_flow(const Tables& t, const ScenarioConfig& sc, int direction, double spacing) {
  FlowMeasurement f;
  const FlowConfig& demand = sc.flow(direction > 0 ? Direction::kForward : Direction::kBackward);
  f.demand_veh_per_h = per_second_to_per_hour(demand.flow_veh_per_s);
  f.source_share_below = CompositeHeadways{demand.free_share, demand.min_headway_s}.share_below(
      demand.flow_veh_per_s, kPlatoonHeadway_s);
  const int own_lanes = direction > 0 ? sc.road.lanes_forward : sc.road.lanes_backward;
  std::map<std::pair<std::int64_t, int>, std::uint64_t> last_crossing;  // (detector, lane) -> step
  std::unordered_map<std::uint64_t, const EgoRow*> ego_at;
  for (const auto& e : t.ego) ego_at[e.step] = &e;
  std::unordered_map<std::uint32_t, double> last_s;
  std::unordered_map<std::uint32_t, std::uint64_t> counted;  // crossings per vehicle
  // Batches by step, over the ego's steps.
  const std::uint64_t first_step = t.ego.empty() ? 0 : t.ego.front().step;
  const std::uint64_t span = t.ego.empty() ? 1 : std::max<std::uint64_t>(1, t.ego.back().step - first_step + 1);
  std::vector<double> batch_crossings(kFlowBatches, 0.0);
  std::vector<double> batch_observed_s(kFlowBatches, 0.0);
  auto batch_of = [&](std::uint64_t step) {
    const std::uint64_t b = (step - std::min(step, first_step)) * kFlowBatches / span;
    return static_cast<std::size_t>(std::min<std::uint64_t>(b, kFlowBatches - 1));
  };
  // The detectors inside the window at both ends of step k (first to last, in detector numbers),
  // if any.
  auto detectors_at = [&](std::uint64_t step) -> std::optional<std::pair<double, double>> {
    auto now = ego_at.find(step);
    auto before = step > 0 ? ego_at.find(step - 1) : ego_at.end();
    if (now == ego_at.end() || before == ego_at.end()) return std::nullopt;
    const WindowBounds w0 = WindowBounds::around(before->second->s_m, sc.window);
    const WindowBounds w1 = WindowBounds::around(now->second->s_m, sc.window);
    const double first = std::ceil(std::max(w0.rear_edge_m, w1.rear_edge_m) / spacing);
    const double last = std::floor(std::min(w0.front_edge_m, w1.front_edge_m) / spacing);
    if (last < first) return std::nullopt;
    return std::make_pair(first, last);
  };
  // Every step of the ego's observes, whether or not a vehicle is about.
  for (const EgoRow& e : t.ego) {
    if (const auto d = detectors_at(e.step)) {
      const double detector_s = (d->second - d->first + 1.0) * sc.step_s;
      f.observed_s += detector_s;
      batch_observed_s[batch_of(e.step)] += detector_s;
    }
  }
  std::unordered_map<std::uint32_t, std::uint64_t> last_step;
  std::size_t i = 0;
  while (i < t.vehicles.size()) {
    const std::uint64_t step = t.vehicles[i].step;
    std::size_t j = i;
    while (j < t.vehicles.size() && t.vehicles[j].step == step) ++j;
    if (const auto d = detectors_at(step)) {
      const auto [first, last] = *d;
      const std::size_t batch = batch_of(step);
      for (std::size_t k = i; k < j; ++k) {
        const VehicleRow& r = t.vehicles[k];
        if (r.direction != direction) continue;
        auto it = last_s.find(r.id);
        if (it == last_s.end() || last_step[r.id] + 1 != step) continue;
        const double a = std::min(it->second, r.s_m);
        const double b = std::max(it->second, r.s_m);
        // detectors x with a < x <= b (forward) or a <= x < b (backward), among those in the window
        const double from = std::max(first, direction > 0 ? std::floor(a / spacing) + 1.0 : std::ceil(a / spacing));
        const double to = std::min(last, direction > 0 ? std::floor(b / spacing) : std::ceil(b / spacing) - 1.0);
        if (to < from) continue;
        const auto crossed = static_cast<std::uint64_t>(to - from + 1.0);
        f.crossings += crossed;
        counted[r.id] += crossed;
        batch_crossings[batch] += static_cast<double>(crossed);
        if (r.lane >= own_lanes) continue;
        for (double x = from; x <= to; x += 1.0) {
          auto [at, fresh] = last_crossing.try_emplace({static_cast<std::int64_t>(x), r.lane}, step);
          if (!fresh) {
            ++f.headways;
            if (static_cast<double>(step - at->second) * sc.step_s < kPlatoonHeadway_s) ++f.headways_below;
            at->second = step;
          }
        }
      }
    }
    for (std::size_t k = i; k < j; ++k) {
      last_s[t.vehicles[k].id] = t.vehicles[k].s_m;
      last_step[t.vehicles[k].id] = step;
    }
    i = j;
  }
  f.vehicles = counted.size();
  if (f.observed_s > 0.0) {
    f.measured_veh_per_h = per_second_to_per_hour(static_cast<double>(f.crossings) / f.observed_s);
    double squares = 0.0;
    for (const auto& [id, c] : counted) squares += static_cast<double>(c) * static_cast<double>(c);
    const double by_vehicles = std::sqrt(squares) / f.observed_s;
    const double by_batches = batch_means_error(batch_crossings, batch_observed_s);
    f.standard_error_veh_per_h = per_second_to_per_hour(std::max(by_vehicles, by_batches));
  }
  return f;
}

PastTheEgo measure_past_ego(const Tables& t, const ScenarioConfig& sc) {
  PastTheEgo p;
  if (t.ego.size() < 2) return p;
  struct EgoAt {
    double s_m;
    bool counted;  // its catch-ups count against the prediction
  };
  std::unordered_map<std::uint64_t, EgoAt> ego_at;
  double counted_steps = 0.0;
  for (const auto& e : t.ego) {
    const bool counted = window_like_reference_road(sc, e.s_m);
    ego_at[e.step] = {e.s_m, counted};
    if (counted) counted_steps += 1.0;
  }
  p.counted_share = counted_steps / static_cast<double>(t.ego.size());
  const WindowConfig& wc = sc.window;
  const double window_m = wc.inner_ahead_m + wc.inner_behind_m + wc.outer_ahead_m + wc.outer_behind_m;
  std::unordered_map<std::uint32_t, std::pair<std::uint64_t, double>> last;  // id -> (step, s - s_ego)
  double forward_vehicle_steps = 0.0;
  double backward_vehicle_steps = 0.0;
  for (const VehicleRow& r : t.vehicles) {
    auto e = ego_at.find(r.step);
    if (e == ego_at.end() || r.region == "outside") continue;
    const double rel = r.s_m - e->second.s_m;
    (r.direction > 0 ? forward_vehicle_steps : backward_vehicle_steps) += 1.0;
    auto it = last.find(r.id);
    if (it != last.end() && it->second.first + 1 == r.step) {
      const double before = it->second.second;
      const bool counted = e->second.counted;
      if (r.direction > 0 && before < 0.0 && rel >= 0.0) {
        ++p.overtaking;
        if (counted) ++p.overtaking_counted;
      }
      if (r.direction > 0 && before >= 0.0 && rel < 0.0) {
        ++p.overtaken;
        if (counted) ++p.overtaken_counted;
      }
      if (r.direction < 0 && before >= 0.0 && rel < 0.0) {
        ++p.met;
        if (counted) ++p.met_counted;
      }
    }
    last[r.id] = {r.step, rel};
  }
  const double steps = static_cast<double>(t.ego.size());
  const double hours = steps * sc.step_s / kSecondsPerHour;
  double u = 0.0;
  for (const auto& e : t.ego) u += e.speed_mps;
  u = mps_to_kph(u / steps);
  const double k_forward = forward_vehicle_steps / steps / (window_m / 1000.0);  // veh/km
  const double k_backward = backward_vehicle_steps / steps / (window_m / 1000.0);
  p.forward_veh_per_h = (static_cast<double>(p.overtaking) - static_cast<double>(p.overtaken)) / hours + k_forward * u;
  p.backward_veh_per_h = static_cast<double>(p.met) / hours - k_backward * u;
  return p;
}

PastTheEgoPrediction predict_past_ego(const Tables& t, const ScenarioConfig& sc) {
  PastTheEgoPrediction p;
  if (t.ego.size() < 2) return p;
  // The streams the run's generator observed (the run's seed is in the recording's info).
  const std::uint64_t seed = generator_seed(t.info.seed);
  const ObservedStream forward(sc, Direction::kForward, StreamObservation{}, observation_seed(seed, Direction::kForward));
  const ObservedStream backward(sc, Direction::kBackward, StreamObservation{},
                                observation_seed(seed, Direction::kBackward));
  for (const auto& e : t.ego) {
    if (!window_like_reference_road(sc, e.s_m)) continue;
    const double u = std::max(0.0, e.speed_mps);
    p.overtaking += forward.vehicles_rear_per_s(u) * sc.step_s;
    p.overtaken += forward.vehicles_front_per_s(u) * sc.step_s;
    p.met += backward.vehicles_oncoming_per_s(u) * sc.step_s;
  }
  return p;
}

Manoeuvres count_manoeuvres(const Tables& t, const ScenarioConfig& sc) {
  Manoeuvres m;
  std::unordered_map<std::uint32_t, std::pair<std::uint64_t, int>> last;  // id -> (step, target lane)
  std::unordered_set<std::uint32_t> overtakers;
  for (const VehicleRow& r : t.vehicles) {
    const int own = r.direction > 0 ? sc.road.lanes_forward : sc.road.lanes_backward;
    auto it = last.find(r.id);
    const bool moving = r.target_lane != r.lane;
    if (moving && it != last.end() && it->second.first + 1 == r.step && it->second.second == r.lane) {
      if (r.target_lane >= own) {
        ++m.overtakings;
        overtakers.insert(r.id);
      } else if (r.lane < own) {
        ++m.lane_changes;
      }
    }
    last[r.id] = {r.step, r.target_lane};
  }
  m.overtakers = overtakers.size();
  return m;
}

RunSummary summarize(const Tables& t, const ScenarioConfig& sc, double spacing) {
  RunSummary s;
  s.steps = t.ego.empty() ? 0 : t.ego.back().step;
  s.simulated_s = static_cast<double>(s.steps) * sc.step_s;
  for (const auto& h : t.handoffs) {
    if (role_of_service(h.from) == Role::kGenerator) {
      ++s.generated;
      if (h.reason == to_string(HandoffReason::kInitialFill)) ++s.initial_fill;
    } else if (h.to_role == "none") {
      ++s.removed;
      if (h.reason == to_string(HandoffReason::kDirector)) ++s.taken_off;
    } else {
      ++s.transfers;
    }
  }
  std::map<std::string, double> sum;
  for (const auto& v : t.vehicles) {
    sum[v.region] += v.speed_mps;
    ++s.samples_in[v.region];
  }
  s.vehicle_samples = t.vehicles.size();
  for (const auto& [region, total] : sum) s.mean_speed_mps[region] = total / static_cast<double>(s.samples_in[region]);
  s.forward = measure_flow(t, sc, 1, spacing);
  s.backward = measure_flow(t, sc, -1, spacing);
  s.past_ego = measure_past_ego(t, sc);
  s.past_ego_predicted = predict_past_ego(t, sc);
  s.manoeuvres = count_manoeuvres(t, sc);
  s.transitions = measure_transitions(t, sc.step_s);
  if (!t.ego.empty()) {
    double total = 0.0;
    for (const auto& e : t.ego) total += e.speed_mps;
    s.ego_mean_speed_mps = total / static_cast<double>(t.ego.size());
    s.ego_distance_m = t.ego.back().s_m - t.ego.front().s_m;
  }
  return s;
}

}  // namespace entourage::recording
