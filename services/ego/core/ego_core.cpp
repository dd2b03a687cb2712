#include "ego/core/ego_core.hpp"

#include <algorithm>

#include "core/random.hpp"
#include "traffic/lateral.hpp"

namespace entourage::ego {

namespace {
// Speed-profile driver: relaxation time towards the target speed.
constexpr double kProfileRelaxation_s = 2.0;
// IDM needs a positive desired speed; a profile target of 0 (stop) is followed by the relaxation.
constexpr double kMinModelDesiredSpeed_mps = 1.0;

// Label of the stand-in driver's random stream (its overtaking decisions), derived from the seed.
constexpr std::uint64_t kEgoDriverStreamLabel = 0x65676f64726976ULL;  // "egodriv"

// Lane changes as the road allows: MOBIL within the own carriageway, passes in the oncoming lane
// on a road with oncoming traffic.
LaneChangeModel ego_lane_changes(const EgoConfig& e, const DrivingEnvironment& env) {
  if (!e.driver.lane_changes || e.driver.use_speed_profile) return LaneChangeModel::kNone;
  return env.two_way() ? LaneChangeModel::kOvertaking : LaneChangeModel::kMobil;
}
}  // namespace

DriverParams ego_driver(const EgoConfig& e, const DrivingEnvironment& env, std::uint64_t seed) {
  DriverParams d;
  IdmParams& idm = d.car_following.idm;
  idm.desired_speed_mps = e.driver.desired_speed_mps;
  idm.time_gap_s = e.driver.time_gap_s;
  idm.max_accel_mps2 = e.driver.max_accel_mps2;
  idm.comfort_decel_mps2 = e.driver.comfort_decel_mps2;
  idm.min_gap_m = e.driver.min_gap_m;
  d.car_following.coolness = e.driver.coolness;
  d.lane_change = ego_lane_changes(e, env);
  d.mobil.politeness = e.driver.politeness;
  d.rng_state = Random::derived(seed, kEgoDriverStreamLabel).next_u64();
  return d;
}

EgoCore::EgoCore(const ScenarioConfig& scenario) : EgoCore(scenario, scenario.seed) {}

EgoCore::EgoCore(const ScenarioConfig& scenario, std::uint64_t seed)
    : scenario_(scenario),
      road_(scenario.road),
      env_(scenario),
      index_(scenario.road.lanes_forward, scenario.road.lanes_backward) {
  const EgoConfig& e = scenario.ego;
  self_.id = kEgoVehicleId;
  self_.direction = Direction::kForward;
  self_.lane = e.lane;
  self_.s_m = e.start_s_m;
  self_.length_m = e.length_m;
  self_.width_m = e.width_m;
  self_.driver = ego_driver(e, env_, seed);
  self_.lane_change.from_lane = self_.lane_change.to_lane = e.lane;
  self_.lane_change.duration_s = self_.driver.lane_change_duration_s;
  if (e.driver.use_speed_profile) {
    self_.driver.car_following.idm.desired_speed_mps = std::max(kMinModelDesiredSpeed_mps, profile_speed_mps(e.start_s_m));
  }
  self_.speed_mps = e.start_speed_mps >= 0.0 ? e.start_speed_mps
                    : e.driver.use_speed_profile ? profile_speed_mps(e.start_s_m)
                                                 : e.driver.desired_speed_mps;
}

double EgoCore::profile_speed_mps(double s_m) const {
  const auto& pts = scenario_.ego.driver.profile;
  if (pts.empty()) return scenario_.ego.driver.desired_speed_mps;
  if (s_m <= pts.front().first) return pts.front().second;
  if (s_m >= pts.back().first) return pts.back().second;
  auto it = std::upper_bound(pts.begin(), pts.end(), s_m, [](double s, const auto& p) { return s < p.first; });
  const auto& [s1, v1] = *it;
  const auto& [s0, v0] = *(it - 1);
  return v0 + (v1 - v0) * (s_m - s0) / (s1 - s0);
}

bool EgoCore::stopping(double t_s) {
  const auto& stops = scenario_.ego.driver.stops;
  if (next_stop_ >= stops.size() || t_s < stops[next_stop_].at_s) return false;
  if (standing_since_s_ < 0.0) {
    if (self_.speed_mps <= stops[next_stop_].speed_mps) standing_since_s_ = t_s;
    return true;
  }
  if (t_s - standing_since_s_ < stops[next_stop_].duration_s) return true;
  ++next_stop_;  // stood long enough: drive on
  standing_since_s_ = -1.0;
  return false;
}

EgoObservation EgoCore::step(Step step, const std::vector<ObservedVehicle>& world_prev) {
  index_.clear();
  if (!scenario_.ego.transparent) {
    for (const auto& o : world_prev) add_to_index(index_, o);
  }
  add_to_index(index_, self_.direction, self_.lane, self_.target_lane(), self_.id, self_.progress_m(),
               self_.speed_mps, self_.accel_mps2, self_.length_m);
  index_.sort();

  const double dt = scenario_.step_s;
  Decision d;
  if (scenario_.ego.driver.use_speed_profile) {
    const double target = profile_speed_mps(self_.s_m);
    self_.driver.car_following.idm.desired_speed_mps = std::max(kMinModelDesiredSpeed_mps, target);
    d = decide(self_, index_, env_);
    const IdmParams& p = self_.driver.car_following.idm;
    const double track = std::clamp((target - self_.speed_mps) / kProfileRelaxation_s, -p.comfort_decel_mps2,
                                    p.max_accel_mps2);
    d.accel_mps2 = std::min(d.accel_mps2, track);
  } else {
    d = decide(self_, index_, env_);
  }
  if (stopping(static_cast<double>(step) * dt)) {
    // Brake comfortably (harder if the model asks) down to the stop's speed, then hold it (stand
    // for a standstill); start no lane change.
    const double brake_mps2 = -self_.driver.car_following.idm.comfort_decel_mps2;
    const double hold_mps = scenario_.ego.driver.stops[next_stop_].speed_mps;
    d.accel_mps2 = self_.speed_mps > hold_mps ? std::min(d.accel_mps2, brake_mps2)
                                              : std::min(d.accel_mps2, std::max(brake_mps2, (hold_mps - self_.speed_mps) / dt));
    if (!self_.lane_change.active()) d.lane_change = self_.lane_change;
    if (!self_.overtaking.active()) d.overtaking = self_.overtaking;
  }
  commit(self_, d, dt);
  return observe(step);
}

bool EgoCore::at_road_end() const {
  return self_.s_m + scenario_.window.inner_ahead_m + scenario_.window.outer_ahead_m >= road_.length_m();
}

EgoObservation EgoCore::observe(Step step) const {
  EgoObservation o;
  o.step = step;
  o.time_s = static_cast<double>(step) * scenario_.step_s;
  o.direction = self_.direction;
  o.lane = self_.lane;
  o.target_lane = self_.target_lane();
  o.indicator = static_cast<std::uint8_t>(self_.indicator());
  o.s_m = self_.s_m;
  o.d_m = lateral_offset_m(road_, self_);
  o.speed_mps = self_.speed_mps;
  o.accel_mps2 = self_.accel_mps2;
  o.length_m = self_.length_m;
  o.width_m = self_.width_m;
  return o;
}

}  // namespace entourage::ego
