#include "behaviour/modified_idm.hpp"

#include <algorithm>

namespace entourage {

double modified_idm_weight(double gap_m, double desired_gap_m, double beta) {
  if (gap_m <= desired_gap_m) return 1.0;
  if (beta <= 1.0 || gap_m >= beta * desired_gap_m) return 0.0;
  const double x = (gap_m / desired_gap_m - 1.0) / (beta - 1.0);
  return 1.0 - x * x * (3.0 - 2.0 * x);
}

double modified_idm_accel_mps2(const IdmParams& p, double beta, double speed_mps, double gap_m,
                               double leader_speed_mps) {
  const double s_star = idm_desired_gap_m(p, speed_mps, speed_mps - leader_speed_mps);
  const double w = modified_idm_weight(gap_m, s_star, beta);
  const double interaction = w > 0.0 ? idm_interaction_mps2(p, speed_mps, gap_m, leader_speed_mps) : 0.0;
  return idm_free_accel_mps2(p, speed_mps) + w * interaction;
}

}  // namespace entourage
