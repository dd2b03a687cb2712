#include "behaviour/gipps.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
// Gipps' free-speed term: v + 2.5 a tau (1 - v/v0) sqrt(0.025 + v/v0) (Gipps 1981, eq. 1).
constexpr double kFreeGain = 2.5;
constexpr double kFreeOffset = 0.025;
}  // namespace

double gipps_free_speed_mps(const IdmParams& idm, const GippsParams& p, double speed_mps) {
  const double r = std::max(0.0, speed_mps) / idm.desired_speed_mps;
  return speed_mps + kFreeGain * idm.max_accel_mps2 * p.reaction_time_s * (1.0 - r) * std::sqrt(kFreeOffset + r);
}

double gipps_safe_speed_mps(const IdmParams& idm, const GippsParams& p, double speed_mps, double gap_m,
                            double leader_speed_mps) {
  const double b = p.max_decel_mps2;
  const double tau = p.reaction_time_s;
  const double room_m = gap_m - idm.min_gap_m;  // dx - S
  const double radicand = b * b * tau * tau +
                          b * (2.0 * room_m - speed_mps * tau +
                               leader_speed_mps * leader_speed_mps / p.leader_decel_estimate_mps2);
  // A negative radicand means no speed is safe any more: stop.
  return std::max(0.0, -b * tau + std::sqrt(std::max(0.0, radicand)));
}

double gipps_accel_mps2(const IdmParams& idm, const GippsParams& p, double speed_mps, const LeaderView* leader) {
  double target = gipps_free_speed_mps(idm, p, speed_mps);
  if (leader != nullptr) target = std::min(target, gipps_safe_speed_mps(idm, p, speed_mps, leader->gap_m, leader->speed_mps));
  return (target - speed_mps) / p.reaction_time_s;
}

}  // namespace entourage
