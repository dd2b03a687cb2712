#include "traffic/driver_draw.hpp"

#include <algorithm>
#include <cmath>

#include "behaviour/model_registry.hpp"

namespace entourage {

namespace {
double standard_normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
// Bisection steps for the median: the interval shrinks by 2^-60, far below any speed resolution.
constexpr int kMedianBisections = 60;
}  // namespace

double draw(const NormalDist& d, Random& rng) { return rng.truncated_normal(d.mean, d.sd, d.min, d.max); }

double median_of(const NormalDist& d) {
  if (d.sd <= 0.0 || d.max <= d.min) return std::clamp(d.mean, d.min, std::max(d.min, d.max));
  const double lo_p = standard_normal_cdf((d.min - d.mean) / d.sd);
  const double hi_p = standard_normal_cdf((d.max - d.mean) / d.sd);
  const double target = 0.5 * (lo_p + hi_p);
  double lo = d.min;
  double hi = d.max;
  for (int i = 0; i < kMedianBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (standard_normal_cdf((mid - d.mean) / d.sd) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

DriverParams draw_driver(const VehicleTypeConfig& type, double desired_speed_mps, std::uint64_t driver_seed,
                         Random& rng) {
  const DriverPopulation& pop = type.driver;
  DriverParams p;
  p.car_following.model = car_following_model_by_name(pop.car_following).value_or(CarFollowingModel::kIdm);
  IdmParams& idm = p.car_following.idm;
  idm.desired_speed_mps = desired_speed_mps;
  idm.time_gap_s = draw(pop.time_gap_s, rng);
  idm.max_accel_mps2 = draw(pop.max_accel_mps2, rng);
  idm.comfort_decel_mps2 = draw(pop.comfort_decel_mps2, rng);
  idm.min_gap_m = draw(pop.min_gap_m, rng);
  idm.accel_exponent = pop.accel_exponent;
  p.car_following.beta = pop.beta;
  p.car_following.coolness = pop.coolness;
  p.lane_change = lane_change_model_by_name(pop.lane_change).value_or(LaneChangeModel::kMobil);
  p.mobil.politeness = draw(pop.politeness, rng);
  p.mobil.change_threshold_mps2 = pop.change_threshold_mps2;
  p.mobil.right_bias_mps2 = pop.right_bias_mps2;
  p.mobil.safe_decel_mps2 = pop.safe_decel_mps2;
  p.lane_change_duration_s = draw(pop.lane_change_duration_s, rng);
  p.max_decel_mps2 = type.max_decel_mps2;
  p.desired_speed_median_mps = median_of(pop.desired_speed_mps);
  GippsParams& gipps = p.car_following.gipps;
  gipps.reaction_time_s = draw(pop.gipps_reaction_time_s, rng);
  gipps.max_decel_mps2 = draw(pop.gipps_max_decel_mps2, rng);
  gipps.leader_decel_estimate_mps2 = pop.gipps_leader_decel_estimate_mps2;
  p.car_following.human_driver = pop.human_driver;
  p.car_following.hdm = pop.hdm;
  p.car_following.hdm.reaction_time_s = draw(pop.hdm_reaction_time_s, rng);
  p.keep_right = type.keep_right;
  p.rng_state = driver_seed;
  return p;
}

Vehicle make_vehicle(VehicleId id, std::uint8_t type_index, const VehicleTypeConfig& type, Direction dir, int lane,
                     double s_m, double speed_mps, const DriverParams& driver) {
  Vehicle v;
  v.id = id;
  v.type_index = type_index;
  v.direction = dir;
  v.lane = lane;
  v.s_m = s_m;
  v.speed_mps = speed_mps;
  v.length_m = type.length_m;
  v.width_m = type.width_m;
  v.lane_change.from_lane = lane;
  v.lane_change.to_lane = lane;
  v.lane_change.duration_s = driver.lane_change_duration_s;
  v.driver = driver;
  return v;
}

}  // namespace entourage
