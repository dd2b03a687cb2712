#include "behaviour/speed_adaptation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace entourage {

namespace {
// Below this curvature a section is treated as straight (as in road/road.cpp): no curve factor.
constexpr double kStraightCurvature = 1e-9;

struct Candidate {
  double median_mps;
  double rotation;
  SpeedFactor factor;
};

bool limit_applies(const SectionConditions& c) { return c.speed_limit_mps > 0.0 && c.reference_limit_mps > 0.0; }

double limit_median_mps(const SectionConditions& c, double basic_median_mps) {
  return basic_median_mps * c.speed_limit_mps / c.reference_limit_mps;
}

double width_median_mps(const SpeedAdaptationParams& p, const SectionConditions& c, double basic_median_mps) {
  const double narrower_m = std::max(0.0, p.reference_lane_width_m - c.lane_width_m);
  return basic_median_mps * std::max(0.0, 1.0 - p.width_reduction_per_m * narrower_m);
}

// Keeps the lower of the best candidate so far and a new one (ties keep the earlier factor).
void take_if_lower(const Candidate& next, bool* have, Candidate* best) {
  if (!*have || next.median_mps < best->median_mps) {
    *best = next;
    *have = true;
  }
}
}  // namespace

SectionMedian section_median(const SpeedAdaptationParams& p, const SectionConditions& c, double basic_median_mps) {
  const SectionMedian none{basic_median_mps, 1.0, SpeedFactor::kNone};
  if (basic_median_mps <= 0.0) return none;

  bool have = false;
  Candidate best{basic_median_mps, 1.0, SpeedFactor::kNone};
  // The limit may lower or raise the median; a limit equal to the reference one does nothing.
  double unconstrained_mps = basic_median_mps;
  if (limit_applies(c)) {
    const double m_limit = limit_median_mps(c, basic_median_mps);
    if (m_limit != basic_median_mps) take_if_lower({m_limit, p.limit_rotation, SpeedFactor::kLimit}, &have, &best);
    unconstrained_mps = std::max(unconstrained_mps, m_limit);
  }
  // A curve binds when it asks for less than the limit would give (even a raised one).
  if (std::abs(c.curvature_per_m) >= kStraightCurvature) {
    const double m_curve = curve_speed_mps(p.curve_lateral_accel_mps2, c.curvature_per_m);
    if (m_curve < unconstrained_mps) take_if_lower({m_curve, p.curve_rotation, SpeedFactor::kCurve}, &have, &best);
  }
  // Width only ever lowers the median.
  const double m_width = width_median_mps(p, c, basic_median_mps);
  if (m_width < basic_median_mps) take_if_lower({m_width, p.width_rotation, SpeedFactor::kWidth}, &have, &best);

  if (!have) return none;
  return SectionMedian{best.median_mps, best.rotation, best.factor};
}

double adapted_desired_speed_mps(const SpeedAdaptationParams& p, const SectionConditions& c,
                                 double basic_desired_mps, double basic_median_mps) {
  const SectionMedian m = section_median(p, c, basic_median_mps);
  if (m.binding == SpeedFactor::kNone) return basic_desired_mps;
  const double r = m.median_mps / basic_median_mps;
  double v = m.median_mps + (basic_desired_mps - basic_median_mps) * std::pow(r, m.rotation);
  // A lowered median never makes a driver faster, a raised one never slower.
  v = r <= 1.0 ? std::min(v, basic_desired_mps) : std::max(v, basic_desired_mps);
  // The floor never lifts a driver above its own basic speed either.
  return std::max(v, std::min(p.min_desired_speed_mps, basic_desired_mps));
}

double curve_speed_mps(double lateral_accel_mps2, double curvature_per_m) {
  const double k = std::abs(curvature_per_m);
  if (k < kStraightCurvature) return std::numeric_limits<double>::infinity();
  return std::sqrt(std::max(0.0, lateral_accel_mps2) / k);
}

double approach_speed_mps(double target_mps, double distance_m, double decel_mps2) {
  return std::sqrt(target_mps * target_mps + 2.0 * std::max(0.0, decel_mps2) * std::max(0.0, distance_m));
}

}  // namespace entourage
