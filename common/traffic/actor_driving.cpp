#include "traffic/actor_driving.hpp"

#include <algorithm>

namespace entourage {

namespace {
// Free space kept to both neighbours in the target lane of a forced change, bumper to bumper.
constexpr double kForcedChangeClearance_m = 1.0;
// Treated as a free road when car following allows at least this share of the driver's a.
constexpr double kFreeRoadShare = 0.95;

bool controlled(const Vehicle& v) { return v.control.mode == ControlMode::kControlled; }
}  // namespace

double actor_desired_speed_mps(const Vehicle& v, double own_mps) {
  const ControlMode m = v.control.mode;
  if (m == ControlMode::kTransported && v.control.speed_mps == kOwnDesiredSpeed_mps) return own_mps;
  return m == ControlMode::kTransported || m == ControlMode::kControlled ? v.control.speed_mps : own_mps;
}

bool eases_down(const Vehicle& v, double director_mps) {
  return v.control.mode == ControlMode::kTransported && director_mps < v.speed_mps;
}

double easing_accel_mps2(const CarFollowingParams& cf, double speed_mps) {
  return std::max(car_following_accel_mps2(cf, speed_mps, nullptr), -cf.idm.comfort_decel_mps2);
}

bool chooses_lanes_freely(const Vehicle& v) {
  const ControlMode m = v.control.mode;
  return m == ControlMode::kAutonomous || m == ControlMode::kReleasing || m == ControlMode::kWithdrawn;
}

int director_lane(const Vehicle& v) {
  return v.control.mode == ControlMode::kTransported ? v.control.lane : -1;
}

double scripted_accel_mps2(const Vehicle& v, double car_following_mps2, double free_road_mps2, double dt_s) {
  const ActorControl& c = v.control;
  const double to_go = c.speed_mps - v.speed_mps;
  const double script = to_go >= 0.0 ? std::min(c.accel_mps2, to_go / dt_s) : std::max(-c.decel_mps2, to_go / dt_s);
  if (car_following_mps2 >= kFreeRoadShare * free_road_mps2) return script;
  return std::min(script, car_following_mps2);
}

double limit_rise_mps2(const Vehicle& v, double accel_mps2, double dt_s) {
  const ControlMode m = v.control.mode;
  if (m != ControlMode::kTransported && m != ControlMode::kReleasing) return accel_mps2;
  const double ceiling = std::max(v.accel_mps2, 0.0) + v.control.max_jerk_mps3 * dt_s;
  return accel_mps2 > v.accel_mps2 ? std::min(accel_mps2, std::max(v.accel_mps2, ceiling)) : accel_mps2;
}

std::optional<LaneChangeState> scripted_lane_change(const Vehicle& v, const LaneIndex& index,
                                                    const DrivingEnvironment& env) {
  const ActorControl& c = v.control;
  if (!controlled(v) || c.lane < 0 || c.lane == v.lane || v.lane_change.active()) return std::nullopt;
  if (c.lane >= env.lanes(v.direction)) return std::nullopt;
  const int target = c.lane < v.lane ? v.lane - 1 : v.lane + 1;
  if (c.force_lane) {
    const double p = v.progress_m();
    const Occupant* ahead = index.leader(v.direction, target, p, v.id);
    const Occupant* behind = index.follower(v.direction, target, p, v.id);
    const double half = 0.5 * v.length_m;
    if (ahead != nullptr && ahead->progress_m - 0.5 * ahead->length_m - (p + half) < kForcedChangeClearance_m) {
      return std::nullopt;
    }
    if (behind != nullptr && (p - half) - (behind->progress_m + 0.5 * behind->length_m) < kForcedChangeClearance_m) {
      return std::nullopt;
    }
  }
  LaneChangeState lc = v.lane_change;
  lc.from_lane = v.lane;
  lc.to_lane = target;
  lc.phase = c.force_lane ? LaneChangePhase::kMoving : LaneChangePhase::kSignalling;
  lc.phase_elapsed_s = 0.0;
  lc.duration_s = c.lane_change_duration_s > 0.0 ? c.lane_change_duration_s : v.driver.lane_change_duration_s;
  return lc;
}

}  // namespace entourage
