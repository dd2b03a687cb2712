#include "traffic/road_sim.hpp"

#include "traffic/driver_draw.hpp"
#include "traffic/entry.hpp"

namespace entourage {

namespace {
constexpr std::uint64_t kDriverStreamLabel = 0x726f616473696d00ULL;
}  // namespace

RoadSim::RoadSim(const ScenarioConfig& scenario, Direction demand_of, RoadSimConfig config, std::uint64_t seed)
    : scenario_(scenario),
      config_(std::move(config)),
      stream_(make_stream(scenario, demand_of)),
      rng_(seed),
      seed_(seed),
      index_(scenario.road.lanes(demand_of), 0),
      crossings_(config_.detectors_m.size()),
      last_crossing_time_(config_.detectors_m.size(),
                          std::vector<double>(static_cast<std::size_t>(scenario.road.lanes(demand_of)),
                                              -std::numeric_limits<double>::infinity())) {
  next_arrival_ = rng_.exponential(1.0);
}

void RoadSim::step() {
  ++steps_;
  arrive();
  perceive();
  enter();
  std::vector<double> before;
  before.reserve(fleet_.size());
  for (const auto& v : fleet_.vehicles()) before.push_back(v.s_m);
  move();
  detect(before);
  remove_finished();
}

void RoadSim::arrive() {
  accumulated_ += stream_.flow_veh_per_s() * scenario_.step_s;
  while (accumulated_ >= next_arrival_) {
    accumulated_ -= next_arrival_;
    next_arrival_ = rng_.exponential(1.0);
    queue_.push_back(stream_.draw_time_mean(rng_));
  }
}

void RoadSim::perceive() { build_index(index_, fleet_, {}, nullptr); }

void RoadSim::enter() {
  while (!queue_.empty()) {
    const SpeedDraw d = queue_.front();
    const VehicleTypeConfig& type = scenario_.vehicle_types[d.type_index];
    const auto spot = find_entry(index_, Direction::kForward, 0.0, d.speed_mps, type);
    if (!spot) return;  // the entrance is full: wait
    const VehicleId id = next_id_++;
    const std::uint64_t driver_seed = Random::derived(seed_, kDriverStreamLabel ^ id).next_u64();
    const DriverParams driver = draw_driver(type, d.speed_mps, scenario_.road.speed_limit_mps, driver_seed, rng_);
    Vehicle v = make_vehicle(id, d.type_index, type, Direction::kForward, spot->lane, 0.0, spot->speed_mps, driver);
    Handoff h;
    h.vehicle = v;
    fleet_.adopt(h, 0, scenario_.step_s);
    add_to_index(index_, Direction::kForward, spot->lane, spot->lane, id, 0.0, spot->speed_mps, 0.0, v.length_m);
    index_.sort();
    queue_.pop_front();
  }
}

void RoadSim::move() {
  const double dt = scenario_.step_s;
  std::vector<Decision> decisions;
  decisions.reserve(fleet_.size());
  for (const Vehicle& v : fleet_.vehicles()) decisions.push_back(decide(v, index_, config_.rules, dt));
  auto& vehicles = fleet_.vehicles();
  for (std::size_t i = 0; i < vehicles.size(); ++i) commit(vehicles[i], decisions[i], dt);
  updates_ += vehicles.size();
}

void RoadSim::detect(const std::vector<double>& before) {
  const auto& vehicles = fleet_.vehicles();
  for (std::size_t d = 0; d < config_.detectors_m.size(); ++d) {
    const double x = config_.detectors_m[d];
    for (std::size_t i = 0; i < vehicles.size() && i < before.size(); ++i) {
      const Vehicle& v = vehicles[i];
      if (!(before[i] < x && v.s_m >= x)) continue;
      double& last = last_crossing_time_[d][static_cast<std::size_t>(v.lane)];
      crossings_[d].push_back({time_s(), v.lane, v.speed_mps, v.driver.desired_speed_mps(), v.type_index, v.id,
                               time_s() - last});
      last = time_s();
    }
  }
}

void RoadSim::remove_finished() {
  exits_ = fleet_.extract_if([&](const Vehicle& v) { return v.s_m > config_.length_m; });
}

}  // namespace entourage
