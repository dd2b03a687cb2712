#include "behaviour/car_following.hpp"

#include "behaviour/cah.hpp"
#include "behaviour/modified_idm.hpp"

namespace entourage {

namespace {
// IDM or the modified IDM behind a leader, with the ACC model's heuristic if the driver has it.
double idm_family_accel_mps2(const CarFollowingParams& p, double base_mps2, double speed_mps, const LeaderView& leader) {
  if (p.coolness <= 0.0 || leader.gap_m <= 0.0) return base_mps2;
  const double cah = cah_accel_mps2(p.idm.max_accel_mps2, speed_mps, leader.gap_m, leader.speed_mps, leader.accel_mps2);
  return acc_blend_mps2(base_mps2, cah, p.coolness, p.idm.comfort_decel_mps2);
}
}  // namespace

double car_following_accel_mps2(const CarFollowingParams& p, double speed_mps, const LeaderView* leader) {
  switch (p.model) {
    case CarFollowingModel::kGipps:
      return gipps_accel_mps2(p.idm, p.gipps, speed_mps, leader);
    case CarFollowingModel::kModifiedIdm:
      if (leader == nullptr) return idm_free_accel_mps2(p.idm, speed_mps);
      return idm_family_accel_mps2(
          p, modified_idm_accel_mps2(p.idm, p.beta, speed_mps, leader->gap_m, leader->speed_mps), speed_mps, *leader);
    case CarFollowingModel::kIdm:
      break;
  }
  if (leader == nullptr) return idm_free_accel_mps2(p.idm, speed_mps);
  return idm_family_accel_mps2(p, idm_accel_mps2(p.idm, speed_mps, leader->gap_m, leader->speed_mps), speed_mps,
                               *leader);
}

}  // namespace entourage
