#include "traffic/road_sim.hpp"

#include <algorithm>

#include "road/window.hpp"

#include "traffic/driver_draw.hpp"
#include "traffic/entry.hpp"

namespace entourage {

namespace {
constexpr std::uint64_t kDriverStreamLabel = 0x726f616473696d00ULL;
constexpr std::size_t kDirections = 2;

RoadSimConfig for_demand_of(const ScenarioConfig& scenario, Direction demand_of, RoadSimConfig config) {
  const bool two_way = scenario.road.kind == RoadKind::kRural && scenario.road.lanes_forward > 0 &&
                       scenario.road.lanes_backward > 0;
  config.forward = demand_of == Direction::kForward || two_way;
  config.backward = demand_of == Direction::kBackward || two_way;
  return config;
}
}  // namespace

ScenarioConfig road_sim_scenario(const ScenarioConfig& scenario, const RoadSimConfig& config) {
  ScenarioConfig c = scenario;
  if (!config.scenario_road) {
    c.road.length_m = config.length_m;
    c.road.segments.clear();
    c.road.speed_zones.clear();
    c.road.no_overtaking.clear();
    c.road.lane_closures.clear();
  }
  return c;
}

bool like_reference_road(const RoadConfig& road, double from_m, double to_m) {
  const auto overlaps = [&](double start_m, double end_m) { return start_m <= to_m && end_m >= from_m; };
  double at_m = 0.0;
  for (const SegmentConfig& seg : road.segments) {
    if (seg.curvature_per_m != 0.0 && overlaps(at_m, at_m + seg.length_m)) return false;
    at_m += seg.length_m;
  }
  const auto any = [&](const auto& zones) {
    return std::any_of(zones.begin(), zones.end(), [&](const auto& z) { return overlaps(z.start_m, z.end_m); });
  };
  return !any(road.speed_zones) && !any(road.no_overtaking) && !any(road.lane_closures);
}

bool window_like_reference_road(const ScenarioConfig& scenario, double ego_s_m) {
  const WindowBounds w = WindowBounds::around(ego_s_m, scenario.window);
  return like_reference_road(scenario.road, w.rear_edge_m, w.front_edge_m);
}

RoadSim::RoadSim(const ScenarioConfig& scenario, RoadSimConfig config, std::uint64_t seed)
    : scenario_(road_sim_scenario(scenario, config)),
      config_(std::move(config)),
      env_(scenario_, config_.rules),
      rng_(seed),
      seed_(seed),
      index_(scenario_.road.lanes_forward, scenario_.road.lanes_backward),
      crossings_(config_.detectors_m.size()) {
  const std::size_t slots =
      static_cast<std::size_t>(std::max(1, scenario_.road.lanes_forward + scenario_.road.lanes_backward));
  last_crossing_time_.assign(config_.detectors_m.size(),
                             std::vector<double>(kDirections * slots, -std::numeric_limits<double>::infinity()));
  for (Direction d : {Direction::kForward, Direction::kBackward}) {
    Source& src = source(d);
    src.active = (d == Direction::kForward ? config_.forward : config_.backward) && scenario_.road.lanes(d) > 0;
    src.stream = std::make_unique<StreamModel>(make_stream(scenario_, d));
    const FlowConfig& flow = d == Direction::kForward ? scenario_.forward : scenario_.backward;
    src.headways = CompositeHeadways{flow.free_share, flow.min_headway_s};
    if (src.active) {
      src.next_arrival = src.headways.poisson() ? rng_.exponential(1.0)
                                                : draw_headway_s(src.headways, src.stream->flow_veh_per_s(), rng_);
    }
  }
}

RoadSim::RoadSim(const ScenarioConfig& scenario, Direction demand_of, RoadSimConfig config, std::uint64_t seed)
    : RoadSim(scenario, for_demand_of(scenario, demand_of, std::move(config)), seed) {}

void RoadSim::step() {
  ++steps_;
  arrive();
  perceive();
  enter(Direction::kForward);
  enter(Direction::kBackward);
  positions_before_.clear();
  for (const auto& v : fleet_.vehicles()) positions_before_.push_back(v.s_m);
  move();
  detect(positions_before_);
  remove_finished();
}

void RoadSim::arrive() {
  for (Source& src : sources_) {
    if (!src.active) continue;
    if (!src.headways.poisson()) {  // composite headways: count down the drawn headway
      src.accumulated += scenario_.step_s;
      while (src.accumulated >= src.next_arrival) {
        src.accumulated -= src.next_arrival;
        src.next_arrival = draw_headway_s(src.headways, src.stream->flow_veh_per_s(), rng_);
        src.queue.push_back(src.stream->draw_time_mean(rng_));
      }
      continue;
    }
    src.accumulated += src.stream->flow_veh_per_s() * scenario_.step_s;
    while (src.accumulated >= src.next_arrival) {
      src.accumulated -= src.next_arrival;
      src.next_arrival = rng_.exponential(1.0);
      src.queue.push_back(src.stream->draw_time_mean(rng_));
    }
  }
}

bool RoadSim::redrive(VehicleId id, const DriverParams& driver) {
  Vehicle* v = fleet_.find(id);
  if (v == nullptr) return false;
  v->driver = driver;
  if (!v->lane_change.active()) v->lane_change.duration_s = driver.lane_change_duration_s;
  return true;
}

void RoadSim::perceive() { build_index(index_, fleet_, {}, nullptr); }

void RoadSim::enter(Direction dir) {
  Source& src = source(dir);
  const double entry_s = dir == Direction::kForward ? 0.0 : scenario_.road.length_m;
  const double progress = sign(dir) * entry_s;
  while (!src.queue.empty()) {
    const SpeedDraw d = src.queue.front();
    const VehicleTypeConfig& type = scenario_.vehicle_types[d.type_index];
    const auto spot = find_entry(index_, dir, progress, d.speed_mps, type, mean_idm(type));
    if (!spot) return;  // the entrance is full: wait
    const VehicleId id = next_id_++;
    const std::uint64_t driver_seed = Random::derived(seed_, kDriverStreamLabel ^ id).next_u64();
    const DriverParams driver = draw_driver(type, d.speed_mps, driver_seed, rng_);
    Vehicle v = make_vehicle(id, d.type_index, type, dir, spot->lane, entry_s, spot->speed_mps, driver);
    Handoff h;
    h.vehicle = v;
    fleet_.adopt(h, 0, scenario_.step_s);
    add_to_index(index_, dir, spot->lane, spot->lane, id, progress, spot->speed_mps, 0.0, v.length_m);
    index_.sort();
    src.queue.pop_front();
    ++counters_.entered;
    if (entry_time_s_.size() <= id) entry_time_s_.resize(id + 1, 0.0);
    entry_time_s_[id] = time_s();
  }
}

void RoadSim::move() {
  const double dt = scenario_.step_s;
  decisions_.clear();
  decisions_.reserve(fleet_.size());
  for (const Vehicle& v : fleet_.vehicles()) decisions_.push_back(decide(v, index_, env_));
  auto& vehicles = fleet_.vehicles();
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    const Decision& d = decisions_[i];
    Vehicle& v = vehicles[i];
    if (d.emergency) ++counters_.emergency_decisions;
    if (!v.lane_change.active() && d.lane_change.active() && !d.overtaking.active()) ++counters_.lane_changes;
    if (d.overtaking.started > v.overtaking.started) ++counters_.overtakings_started;
    if (d.overtaking.aborted > v.overtaking.aborted) ++counters_.overtakings_aborted;
    commit(v, d, dt);
  }
  updates_ += vehicles.size();
}

void RoadSim::detect(const std::vector<double>& before) {
  const auto& vehicles = fleet_.vehicles();
  const std::size_t slots = last_crossing_time_.empty() ? 0 : last_crossing_time_[0].size() / kDirections;
  for (std::size_t d = 0; d < config_.detectors_m.size(); ++d) {
    const double x = config_.detectors_m[d];
    for (std::size_t i = 0; i < vehicles.size() && i < before.size(); ++i) {
      const Vehicle& v = vehicles[i];
      const bool crossed = v.direction == Direction::kForward ? (before[i] < x && v.s_m >= x)
                                                              : (before[i] > x && v.s_m <= x);
      if (!crossed) continue;
      const std::size_t slot = std::min(static_cast<std::size_t>(std::max(0, v.lane)), slots - 1);
      double& last = last_crossing_time_[d][dir_index(v.direction) * slots + slot];
      crossings_[d].push_back({time_s(), v.direction, v.lane, v.speed_mps, v.driver.desired_speed_mps(),
                               v.type_index, v.id, time_s() - last});
      last = time_s();
    }
  }
}

void RoadSim::remove_finished() {
  const double length = scenario_.road.length_m;
  exits_ = fleet_.extract_if([&](const Vehicle& v) {
    return (v.direction == Direction::kForward && v.s_m > length) || (v.direction == Direction::kBackward && v.s_m < 0.0);
  });
  counters_.left += exits_.size();
  for (const Vehicle& v : exits_) {
    const double travel_s = time_s() - entry_time_s_[v.id];
    if (travel_s <= 0.0) continue;
    ++counters_.trips;
    counters_.trip_speed_sum_mps += length / travel_s;
  }
}

}  // namespace entourage
