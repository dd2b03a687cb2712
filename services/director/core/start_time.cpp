#include "director/core/start_time.hpp"

#include <algorithm>
#include <cmath>

namespace entourage::director {

namespace {
constexpr int kBisectionSteps = 60;
constexpr int kIntegrationSteps = 200;  // of the distance integral when the speed floor is reached
// The gap the drive behind a leader divides by never falls below this (the IDM's interaction term
// grows as 1/gap^2: the integration step would otherwise overshoot through a leader it reaches).
constexpr double kFollowGapFloor_m = 0.2;
}  // namespace

void StartTimeEstimator::observe(double speed_mps, double accel_mps2, double dt_s) {
  speed_mps_ = std::max(0.0, speed_mps);
  if (!seen_) {
    accel_mps2_ = accel_mps2;
    seen_ = true;
    return;
  }
  const double w = 1.0 - std::exp(-dt_s / p_.accel_smoothing_s);
  accel_mps2_ += w * (accel_mps2 - accel_mps2_);
}

double StartTimeEstimator::speed_after(double t_s) const {
  const double tau = p_.accel_memory_s;
  return std::max(p_.floor_speed_mps, speed_mps_ + accel_mps2_ * tau * (1.0 - std::exp(-t_s / tau)));
}

double StartTimeEstimator::distance_after(double t_s) const {
  const double tau = p_.accel_memory_s;
  const double v_end = speed_mps_ + accel_mps2_ * tau;  // where the speed tends to
  // The unbounded speed moves monotonically from v to v_end: if both are above the floor, the
  // floor never applies and the integral has a closed form; otherwise integrate numerically.
  if (speed_mps_ >= p_.floor_speed_mps && v_end >= p_.floor_speed_mps) {
    return speed_mps_ * t_s + accel_mps2_ * tau * (t_s - tau * (1.0 - std::exp(-t_s / tau)));
  }
  const double h = t_s / kIntegrationSteps;
  double x = 0.0;
  for (int i = 0; i < kIntegrationSteps; ++i) x += h * speed_after((i + 0.5) * h);
  return x;
}

Prediction StartTimeEstimator::predict(double distance_m) const {
  if (distance_m <= 0.0) return {0.0, speed_after(0.0)};
  if (distance_after(p_.horizon_s) < distance_m) return {};
  double lo = 0.0;
  double hi = p_.horizon_s;
  for (int i = 0; i < kBisectionSteps && hi - lo > 1e-3; ++i) {
    const double mid = 0.5 * (lo + hi);
    (distance_after(mid) < distance_m ? lo : hi) = mid;
  }
  return {hi, speed_after(hi)};
}

Prediction StartTimeEstimator::predict_behind(double distance_m, const LeaderAhead& leader) const {
  const double h = p_.follow_step_s;
  double t = 0.0;
  double x = 0.0;
  double v = speed_mps_;
  IdmParams q = p_.follower;
  while (t < p_.horizon_s) {
    q.desired_speed_mps = std::max({speed_after(t), speed_mps_, p_.floor_speed_mps});
    const double gap = leader.gap_m + leader.speed_mps * t - x;
    const double a = idm_accel_mps2(q, v, std::max(gap, kFollowGapFloor_m), leader.speed_mps);
    const double v_next = std::max(0.0, v + a * h);
    const double dx = 0.5 * (v + v_next) * h;
    if (x + dx >= distance_m) {
      const double share = dx > 0.0 ? (distance_m - x) / dx : 1.0;
      return {t + share * h, v + share * (v_next - v)};
    }
    if (v_next <= 0.0 && leader.speed_mps <= 0.0) return {};  // stands behind a standing leader
    x += dx;
    v = v_next;
    t += h;
  }
  return {};
}

Prediction StartTimeEstimator::predict(double distance_m, const std::optional<LeaderAhead>& leader) const {
  const Prediction free = predict(distance_m);
  if (!leader || distance_m <= 0.0 || free.time_s < 0.0) return free;
  const Prediction behind = predict_behind(distance_m, *leader);
  if (behind.time_s < 0.0) return behind;
  return behind.time_s > free.time_s ? behind : free;
}

}  // namespace entourage::director
