#include "behaviour/car_following.hpp"

#include "behaviour/modified_idm.hpp"

namespace entourage {

double car_following_accel_mps2(const CarFollowingParams& p, double speed_mps, const LeaderView* leader) {
  switch (p.model) {
    case CarFollowingModel::kGipps:
      return gipps_accel_mps2(p.idm, p.gipps, speed_mps, leader);
    case CarFollowingModel::kModifiedIdm:
      if (leader == nullptr) return idm_free_accel_mps2(p.idm, speed_mps);
      return modified_idm_accel_mps2(p.idm, p.beta, speed_mps, leader->gap_m, leader->speed_mps);
    case CarFollowingModel::kIdm:
      break;
  }
  if (leader == nullptr) return idm_free_accel_mps2(p.idm, speed_mps);
  return idm_accel_mps2(p.idm, speed_mps, leader->gap_m, leader->speed_mps);
}

}  // namespace entourage
