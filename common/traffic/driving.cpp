#include "traffic/driving.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
// Below this gap to a slower leader, the emergency regime stops the vehicle at the latest here.
constexpr double kEmergencyStandstillGap_m = 0.5;

LeaderView view_of(const Occupant& leader, const Vehicle& v) {
  return LeaderView{gap_between(leader, v.progress_m(), v.length_m), leader.speed_mps, leader.accel_mps2};
}

// Acceleration another driver (speed `speed_mps`, progress `progress_m`, length `length_m`) would
// have behind `leader`, estimated with the deciding driver's own parameters (a driver judges
// others by how it would drive itself; this also keeps decisions independent of who owns whom).
double estimated_accel(const Vehicle& judge, double progress_m, double speed_mps, double length_m,
                       const Occupant* leader) {
  if (leader == nullptr) return idm_free_accel_mps2(judge.driver.car_following.idm, speed_mps);
  const LeaderView lv{gap_between(*leader, progress_m, length_m), leader->speed_mps, leader->accel_mps2};
  return car_following_accel_mps2(judge.driver.car_following, speed_mps, &lv);
}

Occupant as_occupant(const Vehicle& v) {
  return Occupant{v.id, v.progress_m(), v.speed_mps, v.accel_mps2, v.length_m};
}

bool lane_allowed(const Vehicle& v, int lane, int lanes) {
  if (lane < 0 || lane >= lanes) return false;
  return !v.driver.keep_right || lane <= v.lane;  // keep-right vehicles only move right
}
}  // namespace

const Occupant* leader_of(const Vehicle& v, const LaneIndex& index, int lane) {
  return index.leader(v.direction, lane, v.progress_m(), v.id);
}

double accel_behind(const Vehicle& v, const Occupant* leader, bool* emergency) {
  if (leader == nullptr) return car_following_accel_mps2(v.driver.car_following, v.speed_mps, nullptr);
  const LeaderView lv = view_of(*leader, v);
  double a = car_following_accel_mps2(v.driver.car_following, v.speed_mps, &lv);
  // Emergency regime: the deceleration that stops the approach before the gap closes, assuming
  // the leader keeps its speed; applied when it exceeds what the model asks for.
  const double closing = v.speed_mps - leader->speed_mps;
  if (closing > 0.0) {
    const double room = lv.gap_m - kEmergencyStandstillGap_m;
    const double needed = room > 0.0 ? closing * closing / (2.0 * room) : v.driver.max_decel_mps2;
    if (needed > v.driver.car_following.idm.comfort_decel_mps2 && -needed < a) {
      a = -needed;
      if (emergency != nullptr) *emergency = true;
    }
  }
  return std::max(a, -v.driver.max_decel_mps2);
}

LaneChangeOption evaluate_lane_change(const Vehicle& v, const LaneIndex& index, int target) {
  LaneChangeOption opt;
  opt.target_lane = target;
  const Occupant* lead_now = leader_of(v, index, v.lane);
  const Occupant* lead_new = leader_of(v, index, target);
  const Occupant* follow_new = index.follower(v.direction, target, v.progress_m(), v.id);
  const Occupant* follow_old = index.follower(v.direction, v.lane, v.progress_m(), v.id);
  const Occupant self = as_occupant(v);

  // No overlap with the vehicles beside us in the target lane.
  if (lead_new != nullptr && gap_between(*lead_new, v.progress_m(), v.length_m) <= 0.0) return opt;
  if (follow_new != nullptr && gap_between(self, follow_new->progress_m, follow_new->length_m) <= 0.0) return opt;

  MobilSituation s;
  s.to_right = target < v.lane;
  s.self_now_mps2 = accel_behind(v, lead_now);
  s.self_after_mps2 = accel_behind(v, lead_new);
  if (follow_new != nullptr) {
    s.new_follower_now_mps2 =
        estimated_accel(v, follow_new->progress_m, follow_new->speed_mps, follow_new->length_m, lead_new);
    s.new_follower_after_mps2 =
        estimated_accel(v, follow_new->progress_m, follow_new->speed_mps, follow_new->length_m, &self);
  }
  if (follow_old != nullptr) {
    s.old_follower_now_mps2 =
        estimated_accel(v, follow_old->progress_m, follow_old->speed_mps, follow_old->length_m, &self);
    s.old_follower_after_mps2 =
        estimated_accel(v, follow_old->progress_m, follow_old->speed_mps, follow_old->length_m, lead_now);
  }
  const MobilDecision d = mobil_decide(v.driver.mobil, s);
  opt.safe = d.safe;
  opt.advantage_mps2 = d.advantage_mps2;
  return opt;
}

namespace {
LaneChangeState plan_lane_change(const Vehicle& v, const LaneIndex& index, const DrivingRules& rules,
                                 double dt_s) {
  LaneChangeState lc = v.lane_change;
  const int lanes = index.lanes(v.direction);
  switch (lc.phase) {
    case LaneChangePhase::kNone: {
      lc.since_last_change_s += dt_s;
      if (v.driver.lane_change != LaneChangeModel::kMobil || lc.since_last_change_s < rules.min_interval_s) break;
      LaneChangeOption best;
      bool found = false;
      for (int target : {v.lane - 1, v.lane + 1}) {  // right first: it wins ties
        if (!lane_allowed(v, target, lanes)) continue;
        const LaneChangeOption opt = evaluate_lane_change(v, index, target);
        if (opt.safe && opt.advantage_mps2 > 0.0 && (!found || opt.advantage_mps2 > best.advantage_mps2)) {
          best = opt;
          found = true;
        }
      }
      if (found) {
        lc.from_lane = v.lane;
        lc.to_lane = best.target_lane;
        lc.phase = LaneChangePhase::kSignalling;
        lc.phase_elapsed_s = 0.0;
        lc.duration_s = v.driver.lane_change_duration_s;
      }
      break;
    }
    case LaneChangePhase::kSignalling: {
      lc.phase_elapsed_s += dt_s;
      if (lc.phase_elapsed_s < rules.signal_s) break;
      const LaneChangeOption opt = evaluate_lane_change(v, index, lc.to_lane);
      if (opt.safe) {
        lc.phase = LaneChangePhase::kMoving;
        lc.phase_elapsed_s = 0.0;
      } else if (lc.phase_elapsed_s >= rules.max_signal_wait_s) {
        lc.phase = LaneChangePhase::kNone;  // give up; the interval restarts
        lc.to_lane = lc.from_lane;
        lc.since_last_change_s = 0.0;
      }
      break;
    }
    case LaneChangePhase::kMoving:
      lc.phase_elapsed_s += dt_s;
      break;
  }
  return lc;
}
}  // namespace

Decision decide(const Vehicle& v, const LaneIndex& index, const DrivingRules& rules, double dt_s) {
  Decision d;
  d.lane_change = plan_lane_change(v, index, rules, dt_s);
  bool emergency = false;
  double a = accel_behind(v, leader_of(v, index, v.lane), &emergency);
  if (v.lane_change.moving()) {  // occupying both lanes: respect the leader in each
    a = std::min(a, accel_behind(v, leader_of(v, index, v.lane_change.to_lane), &emergency));
  }
  d.accel_mps2 = a;
  d.emergency = emergency;
  return d;
}

void commit(Vehicle& v, const Decision& d, double dt_s) {
  v.lane_change = d.lane_change;
  const double a = d.accel_mps2;
  const double v_end = v.speed_mps + a * dt_s;
  double ds = 0.0;
  if (v_end < 0.0) {  // stops within the step
    ds = a < 0.0 ? -v.speed_mps * v.speed_mps / (2.0 * a) : 0.0;
    v.speed_mps = 0.0;
  } else {
    ds = 0.5 * (v.speed_mps + v_end) * dt_s;
    v.speed_mps = v_end;
  }
  v.accel_mps2 = a;
  v.s_m += sign(v.direction) * ds;

  LaneChangeState& lc = v.lane_change;
  if (lc.moving() && lc.phase_elapsed_s >= lc.duration_s) {
    v.lane = lc.to_lane;
    lc.from_lane = lc.to_lane;
    lc.phase = LaneChangePhase::kNone;
    lc.phase_elapsed_s = 0.0;
    lc.since_last_change_s = 0.0;
  }
}

void continue_lane_change(Vehicle& v, double dt_s) {
  LaneChangeState& lc = v.lane_change;
  lc.since_last_change_s += dt_s;
  if (lc.phase == LaneChangePhase::kSignalling) {
    lc.phase = LaneChangePhase::kNone;
    lc.to_lane = lc.from_lane = v.lane;
  } else if (lc.moving()) {
    lc.phase_elapsed_s += dt_s;
    if (lc.phase_elapsed_s >= lc.duration_s) {
      v.lane = lc.to_lane;
      lc.from_lane = lc.to_lane;
      lc.phase = LaneChangePhase::kNone;
      lc.phase_elapsed_s = 0.0;
      lc.since_last_change_s = 0.0;
    }
  }
}

const Occupant* nearest_leader(const Vehicle& v, const LaneIndex& index) {
  const Occupant* best = leader_of(v, index, v.lane);
  if (v.lane_change.moving()) {
    const Occupant* other = leader_of(v, index, v.lane_change.to_lane);
    if (other != nullptr && (best == nullptr || other->progress_m < best->progress_m)) best = other;
  }
  return best;
}

}  // namespace entourage
