#include "meso/core/equilibrium.hpp"

#include <algorithm>
#include <cmath>

namespace entourage::meso {

namespace {
// The table reaches this many desired gaps (s0 + v0 T); beyond it IDM is within 0.3 % of v0.
constexpr double kTableReachInSafeGaps = 20.0;
constexpr int kBisectionSteps = 12;  // within v0 / 4096 (8 mm/s at 33 m/s): far below the interpolation error

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

EquilibriumSpeed::EquilibriumSpeed(const CarFollowingParams& p)
    : params_(p), desired_mps_(p.idm.desired_speed_mps), known_(0) {
  max_gap_m_ = kTableReachInSafeGaps * (p.idm.min_gap_m + p.idm.desired_speed_mps * p.idm.time_gap_s);
}

double EquilibriumSpeed::point(std::size_t i) const {
  const std::uint64_t bit = std::uint64_t{1} << i;
  if ((known_ & bit) == 0) {
    const double x = static_cast<double>(i) / (kPoints - 1);
    speed_mps_[i] = equilibrium_by_bisection(params_, max_gap_m_ * x * x);
    known_ |= bit;
  }
  return speed_mps_[i];
}

double EquilibriumSpeed::at(double gap_m) const {
  if (gap_m >= max_gap_m_) return desired_mps_;
  if (gap_m <= 0.0) return point(0);
  const double pos = std::sqrt(gap_m / max_gap_m_) * (kPoints - 1);
  const auto i = static_cast<std::size_t>(pos);
  if (i + 1 >= kPoints) return point(kPoints - 1);  // a gap a rounding error short of max_gap_m_
  const double f = pos - static_cast<double>(i);
  const double lo = point(i);
  return lo + f * (point(i + 1) - lo);
}

}  // namespace entourage::meso
