#include "meso/core/equilibrium.hpp"

#include <algorithm>
#include <cmath>

namespace entourage::meso {

namespace {
// The table reaches this many desired gaps (s0 + v0 T); beyond it IDM is within 0.3 % of v0.
constexpr double kTableReachInSafeGaps = 20.0;
constexpr int kBisectionSteps = 40;

double equilibrium_by_bisection(const CarFollowingParams& p, double gap_m) {
  double lo = 0.0;
  double hi = p.idm.desired_speed_mps;
  for (int i = 0; i < kBisectionSteps; ++i) {
    const double v = 0.5 * (lo + hi);
    const LeaderView leader{gap_m, v, 0.0};
    (car_following_accel_mps2(p, v, &leader) > 0.0 ? lo : hi) = v;
  }
  return 0.5 * (lo + hi);
}
}  // namespace

EquilibriumSpeed::EquilibriumSpeed(const CarFollowingParams& p) : desired_mps_(p.idm.desired_speed_mps) {
  max_gap_m_ = kTableReachInSafeGaps * (p.idm.min_gap_m + p.idm.desired_speed_mps * p.idm.time_gap_s);
  for (int i = 0; i < kPoints; ++i) {
    const double x = static_cast<double>(i) / (kPoints - 1);
    speed_mps_[static_cast<std::size_t>(i)] = equilibrium_by_bisection(p, max_gap_m_ * x * x);
  }
}

double EquilibriumSpeed::at(double gap_m) const {
  if (gap_m >= max_gap_m_) return desired_mps_;
  if (gap_m <= 0.0) return speed_mps_[0];
  const double pos = std::sqrt(gap_m / max_gap_m_) * (kPoints - 1);
  const auto i = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(i);
  return speed_mps_[i] + f * (speed_mps_[i + 1] - speed_mps_[i]);
}

}  // namespace entourage::meso
