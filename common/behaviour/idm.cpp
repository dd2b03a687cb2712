#include "behaviour/idm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace entourage {

namespace {
// Gaps below this are treated as this (a vehicle touching its leader brakes as hard as the
// model allows instead of dividing by zero).
constexpr double kMinGapForModel = 0.01;
}  // namespace

double idm_speed_ratio_term(const IdmParams& p, double speed_mps) {
  const double r = std::max(0.0, speed_mps) / p.desired_speed_mps;
  if (p.accel_exponent == 4.0) {
    const double r2 = r * r;
    return r2 * r2;
  }
  return std::pow(r, p.accel_exponent);
}

double idm_desired_gap_m(const IdmParams& p, double speed_mps, double approach_rate_mps) {
  const double dynamic = speed_mps * p.time_gap_s +
                         speed_mps * approach_rate_mps /
                             (2.0 * std::sqrt(p.max_accel_mps2 * p.comfort_decel_mps2));
  return p.min_gap_m + std::max(0.0, dynamic);
}

double idm_free_accel_mps2(const IdmParams& p, double speed_mps) {
  return p.max_accel_mps2 * (1.0 - idm_speed_ratio_term(p, speed_mps));
}

double idm_interaction_mps2(const IdmParams& p, double speed_mps, double gap_m, double leader_speed_mps) {
  const double s_star = idm_desired_gap_m(p, speed_mps, speed_mps - leader_speed_mps);
  const double ratio = s_star / std::max(gap_m, kMinGapForModel);
  return -p.max_accel_mps2 * ratio * ratio;
}

double idm_accel_mps2(const IdmParams& p, double speed_mps, double gap_m, double leader_speed_mps) {
  return idm_free_accel_mps2(p, speed_mps) + idm_interaction_mps2(p, speed_mps, gap_m, leader_speed_mps);
}

double idm_equilibrium_gap_m(const IdmParams& p, double speed_mps) {
  const double denom = 1.0 - idm_speed_ratio_term(p, speed_mps);
  if (denom <= 0.0) return std::numeric_limits<double>::infinity();
  return idm_desired_gap_m(p, speed_mps, 0.0) / std::sqrt(denom);
}

}  // namespace entourage
