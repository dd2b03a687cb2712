#pragma once
// Speed adaptation (thesis ch. 2.3.4, after Brodin & Carlsson 1986): each driver draws a basic
// desired speed from its type's distribution, stated for the road's reference conditions (its
// base speed limit, a straight road, the reference lane width). A road section with other
// conditions moves the distribution: its median is reduced (or raised) by the factor that binds
// most, and the distribution is rotated around its median so that drivers far from the median are
// moved more than those near it:
//
//   m_limit = m_basic * limit / reference_limit                  (speed-limit sub-model)
//   m_curve = sqrt(curve_lateral_accel / |curvature|)             (curvature sub-model)
//   m_width = m_basic * (1 - width_reduction_per_m * max(0, reference_width - width))
//   m       = the smallest of the three, r = m / m_basic, rho the binding factor's rotation
//   v       = m + (v_basic - m_basic) * r^rho
//
// With rho = 1 every driver's speed is scaled by r (a pure relative model, as Barcelo & Casas
// 2002); rho > 1 rotates the distribution further, so that fast drivers are affected more by a
// lower limit or a curve than slow ones (the thesis's Figure 2.11). A section never makes a driver
// faster than its basic desired speed when it lowers the median, nor slower when it raises it.
//
// A driver approaching a section with a lower desired speed starts slowing in time: its desired
// speed at a distance x before that section is sqrt(v_section^2 + 2 approach_decel x).
//
// Pure functions; the road's sections are in traffic/speed_sections.hpp.

namespace entourage {

struct SpeedAdaptationParams {
  double limit_rotation = 1.5;                 // rho for the speed-limit sub-model
  double curve_lateral_accel_mps2 = 2.0;       // the median driver's lateral acceleration in curves
  double curve_rotation = 2.0;                 // rho for the curvature sub-model
  double reference_lane_width_m = 3.5;         // the width the basic desired speeds are stated for
  double width_reduction_per_m = 0.08;         // relative median reduction per metre narrower
  double width_rotation = 1.0;                 // rho for the width sub-model
  double approach_decel_mps2 = 1.0;            // slowing down towards a slower section ahead
  double min_desired_speed_mps = 2.0;          // no section makes a desired speed lower than this
};

// The conditions of one road section.
struct SectionConditions {
  double speed_limit_mps = 0.0;
  double reference_limit_mps = 0.0;  // the limit the basic desired speeds are stated for
  double curvature_per_m = 0.0;      // signed; only its magnitude matters
  double lane_width_m = 3.5;
};

enum class SpeedFactor { kNone, kLimit, kCurve, kWidth };

// The median of the section's desired-speed distribution, and which factor set it.
struct SectionMedian {
  double median_mps = 0.0;
  double rotation = 1.0;
  SpeedFactor binding = SpeedFactor::kNone;
};

SectionMedian section_median(const SpeedAdaptationParams& p, const SectionConditions& c, double basic_median_mps);

// A driver's desired speed on the section, from its basic desired speed and the median of its
// type's basic distribution.
double adapted_desired_speed_mps(const SpeedAdaptationParams& p, const SectionConditions& c,
                                 double basic_desired_mps, double basic_median_mps);

// The speed at which a curve is driven with the given lateral acceleration (infinite if straight).
double curve_speed_mps(double lateral_accel_mps2, double curvature_per_m);

// The highest speed from which `target_mps` is reached within `distance_m` at `decel_mps2`.
double approach_speed_mps(double target_mps, double distance_m, double decel_mps2);

}  // namespace entourage
