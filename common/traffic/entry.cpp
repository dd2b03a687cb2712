#include "traffic/entry.hpp"

#include <algorithm>

#include "behaviour/idm.hpp"

namespace entourage {

namespace {
// A new vehicle never starts closer than this share of the time gap behind another.
constexpr double kMinTimeGapShare = 0.5;
// Nothing enters a lane in which a vehicle of the other direction (an overtaker) would meet it
// within this time.
constexpr double kOncomingClearance_s = 8.0;

bool oncoming_in_the_way(const LaneIndex& index, Direction dir, int lane, double progress_m, double speed_mps,
                         const VehicleTypeConfig& type, const IdmParams& driver) {
  const Occupant* o = index.oncoming(dir, lane, progress_m - type.length_m);
  if (o == nullptr) return false;
  const double gap_m = oncoming_gap(*o, progress_m, type.length_m);
  return gap_m < kOncomingClearance_s * (speed_mps + o->speed_mps) + driver.min_gap_m;
}
}  // namespace

IdmParams mean_idm(const VehicleTypeConfig& type) {
  IdmParams p;
  p.time_gap_s = type.driver.time_gap_s.mean;
  p.max_accel_mps2 = type.driver.max_accel_mps2.mean;
  p.comfort_decel_mps2 = type.driver.comfort_decel_mps2.mean;
  p.min_gap_m = type.driver.min_gap_m.mean;
  return p;
}

double wanted_gap_m(const IdmParams& p, double speed_mps, double leader_speed_mps) {
  return std::max(idm_desired_gap_m(p, speed_mps, speed_mps - leader_speed_mps),
                  p.min_gap_m + kMinTimeGapShare * speed_mps * p.time_gap_s);
}

std::optional<EntrySpot> find_entry(const LaneIndex& index, Direction dir, double progress_m, double speed_mps,
                                    const VehicleTypeConfig& type, const IdmParams& driver, int preferred_lane,
                                    EntryPolicy policy) {
  const int lanes = index.lanes(dir);
  std::optional<EntrySpot> best;
  for (int lane = 0; lane < (type.keep_right ? std::min(1, lanes) : lanes); ++lane) {
    if (oncoming_in_the_way(index, dir, lane, progress_m, speed_mps, type, driver)) continue;
    const auto around = index.neighbours(dir, lane, progress_m, kNoVehicle);
    const Occupant* leader = around.leader;
    const Occupant* follower = around.follower;
    double v = speed_mps;
    if (leader != nullptr) {
      const double gap = gap_between(*leader, progress_m, type.length_m);
      if (policy == EntryPolicy::kMatchLeader && gap < wanted_gap_m(driver, v, leader->speed_mps)) {
        v = std::min(v, leader->speed_mps);
      }
      if (gap < wanted_gap_m(driver, v, leader->speed_mps)) continue;
    }
    if (follower != nullptr) {
      const Occupant self{kNoVehicle, progress_m, v, 0.0, type.length_m};
      if (gap_between(self, follower->progress_m, follower->length_m) < wanted_gap_m(driver, follower->speed_mps, v)) {
        continue;
      }
    }
    const bool faster = !best || v > best->speed_mps + 1e-9;
    const bool preferred_tie = best && lane == preferred_lane && v >= best->speed_mps - 1e-9;
    if (faster || preferred_tie) best = EntrySpot{lane, v};
  }
  return best;
}

}  // namespace entourage
