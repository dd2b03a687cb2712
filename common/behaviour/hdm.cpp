#include "behaviour/hdm.hpp"

#include <algorithm>
#include <cmath>

#include "behaviour/modified_idm.hpp"

namespace entourage {

namespace {
// A perceived gap is never taken as shorter than this (the errors multiply a positive gap, so
// this only guards the model's division).
constexpr double kMinPerceivedGap_m = 0.01;

// The base model's interaction term with one leader, as perceived.
double interaction_mps2(const CarFollowingParams& base, double speed_mps, double gap_m, double approach_mps) {
  const double leader_speed_mps = speed_mps - approach_mps;
  const double term = idm_interaction_mps2(base.idm, speed_mps, gap_m, leader_speed_mps);
  if (base.model != CarFollowingModel::kModifiedIdm) return term;
  const double s_star = idm_desired_gap_m(base.idm, speed_mps, approach_mps);
  return modified_idm_weight(gap_m, s_star, base.beta) * term;
}
}  // namespace

void advance_hdm_errors(HdmErrors& e, const HdmParams& p, double dt_s, SmallRandom& rng) {
  if (p.error_persistence_s <= 0.0) {  // no persistence: white noise
    e.w_distance = rng.normal();
    e.w_approach = rng.normal();
    return;
  }
  const double keep = std::exp(-dt_s / p.error_persistence_s);
  const double fresh = std::sqrt(std::max(0.0, 1.0 - keep * keep));
  e.w_distance = keep * e.w_distance + fresh * rng.normal();
  e.w_approach = keep * e.w_approach + fresh * rng.normal();
}

double hdm_instant_accel_mps2(const CarFollowingParams& base, const HdmParams& p, const HdmErrors& e,
                              double speed_mps, const LeaderView* leaders, std::size_t count) {
  const double free = idm_free_accel_mps2(base.idm, speed_mps);
  const std::size_t n = std::min(count, static_cast<std::size_t>(std::max(1, p.anticipated_leaders)));
  if (n == 0) return free;
  const double gap_factor = std::exp(p.distance_error * e.w_distance);
  double sum = 0.0;
  double norm = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const LeaderView& l = leaders[j];
    const double gap_m = std::max(kMinPerceivedGap_m, l.gap_m * gap_factor);
    const double approach_mps = (speed_mps - l.speed_mps) - l.gap_m * p.inverse_ttc_error_per_s * e.w_approach;
    sum += interaction_mps2(base, speed_mps, gap_m, approach_mps);
    const double rank = static_cast<double>(j + 1);
    norm += 1.0 / (rank * rank);
  }
  return free + sum / norm;
}

void HdmMemory::push(double a_mps2) {
  const std::size_t keep = std::min<std::size_t>(count, kCapacity - 1);
  for (std::size_t i = keep; i > 0; --i) decided_mps2[i] = decided_mps2[i - 1];
  decided_mps2[0] = static_cast<float>(a_mps2);
  count = static_cast<std::uint8_t>(keep + 1);
}

double HdmMemory::delayed(double current_mps2, double delay_s, double dt_s) const {
  if (delay_s <= 0.0 || dt_s <= 0.0) return current_mps2;
  // Entry k of the virtual sequence is the decision k steps ago: 0 the current one, k >= 1 the
  // memory's entry k - 1.
  auto entry = [&](std::size_t k) -> double {
    if (k == 0 || count == 0) return current_mps2;
    return decided_mps2[std::min<std::size_t>(k - 1, count - 1u)];
  };
  const double steps = delay_s / dt_s;
  const auto k = static_cast<std::size_t>(std::floor(steps));
  const double frac = steps - static_cast<double>(k);
  return (1.0 - frac) * entry(k) + frac * entry(k + 1);
}

}  // namespace entourage
