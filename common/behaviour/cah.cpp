#include "behaviour/cah.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

double cah_accel_mps2(double max_accel_mps2, double speed_mps, double gap_m, double leader_speed_mps,
                      double leader_accel_mps2) {
  const double a_tilde = std::min(leader_accel_mps2, max_accel_mps2);
  const double v = speed_mps;
  const double vl = leader_speed_mps;
  const double denominator = vl * vl - 2.0 * gap_m * a_tilde;
  // The leader would stop before the gap closes: the deceleration that stops just behind it.
  if (vl * (v - vl) <= -2.0 * gap_m * a_tilde && denominator > 0.0) return v * v * a_tilde / denominator;
  const double closing = std::max(0.0, v - vl);
  return a_tilde - closing * closing / (2.0 * gap_m);
}

double acc_blend_mps2(double idm_mps2, double cah_mps2, double coolness, double comfort_decel_mps2) {
  if (idm_mps2 >= cah_mps2) return idm_mps2;
  return (1.0 - coolness) * idm_mps2 +
         coolness * (cah_mps2 + comfort_decel_mps2 * std::tanh((idm_mps2 - cah_mps2) / comfort_decel_mps2));
}

}  // namespace entourage
