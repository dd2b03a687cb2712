#include "meso/core/meso_lanes.hpp"

#include "traffic/fleet.hpp"
#include "traffic/lane_changes.hpp"

namespace entourage::meso {

namespace {

double safe_gap_m(const IdmParams& p, double speed_mps) { return p.min_gap_m + speed_mps * p.time_gap_s; }

// Room for `v` behind `leader`: at least `ahead_factor` safe gaps.
bool room_behind(const Vehicle& v, const Occupant& leader, double ahead_factor) {
  return gap_between(leader, v.progress_m(), v.length_m) >= ahead_factor * safe_gap_m(v.driver.car_following.idm, v.speed_mps);
}

// Room for `follower` behind `v`: the follower keeps its safe gap (at its speed, `v`'s time gap),
// and closing in, it would not brake harder than MOBIL's safe deceleration behind `v` by
// `follower_model` (its own where meso drives it, as micro's drivers judge: model_of). The safe
// gap alone let a car change in 50 m ahead of one 9 m/s faster, which braked at 9 m/s^2 (freeway,
// seed 1, stop 33).
bool room_ahead_of(const Vehicle& v, const Occupant& follower, const CarFollowingParams& follower_model) {
  const Occupant self = as_occupant(v);
  if (gap_between(self, follower.progress_m, follower.length_m) < safe_gap_m(v.driver.car_following.idm, follower.speed_mps)) {
    return false;
  }
  return follower_accel_mps2(follower_model, follower, &self) >= -v.driver.mobil.safe_decel_mps2;
}

// Room for `v` in `lane`: the gap ahead is at least `ahead_factor` safe gaps and the follower
// there keeps its own safe gap. Returns the leader there (or nullptr) through `leader_out`.
bool has_room(const Vehicle& v, const LaneIndex& index, int lane, double ahead_factor, const Occupant** leader_out) {
  const auto around = index.neighbours(v.direction, lane, v.progress_m(), v.id);
  *leader_out = around.leader;
  if (around.leader != nullptr && !room_behind(v, *around.leader, ahead_factor)) return false;
  return around.follower == nullptr ||
         room_ahead_of(v, *around.follower, model_of(around.follower->id, index, v.driver.car_following));
}

bool just_begun(const Vehicle& v, const LaneRules& rules) {
  const LaneChangeState& lc = v.lane_change;
  return lc.moving() && lc.lateral_fraction() <= rules.call_off_fraction;
}

}  // namespace

std::optional<int> choose_lane(const Vehicle& v, const LaneIndex& index, double gap_ahead_m, const LaneRules& rules,
                               int must_target) {
  if (v.lane_change.active()) return std::nullopt;
  if (must_target >= 0) {
    const Occupant* leader_there = nullptr;
    if (has_room(v, index, must_target, 1.0, &leader_there)) return must_target;
    return std::nullopt;
  }
  if (v.lane_change.since_last_change_s < rules.min_interval_s) return std::nullopt;
  if (v.driver.lane_change == LaneChangeModel::kNone) return std::nullopt;
  const IdmParams& p = v.driver.car_following.idm;
  const int lanes = index.lanes(v.direction);
  const double v_gap = gap_ahead_m < 0.0 ? p.desired_speed_mps : (gap_ahead_m - p.min_gap_m) / p.time_gap_s;
  const bool blocked = v_gap < p.desired_speed_mps - rules.blocked_speed_loss_mps;
  const Occupant* leader_there = nullptr;
  if (blocked && !v.driver.keep_right && v.lane + 1 < lanes && has_room(v, index, v.lane + 1, 1.0, &leader_there)) {
    // Looked up only here: most vehicles are not blocked, and this runs at every step.
    const Occupant* leader_now = index.leader(v.direction, v.lane, v.progress_m(), v.id);
    if (leader_there == nullptr || leader_now == nullptr || leader_there->speed_mps > leader_now->speed_mps) {
      return v.lane + 1;
    }
  }
  if (v.lane > 0 && has_room(v, index, v.lane - 1, rules.keep_right_gap_factor, &leader_there) &&
      (leader_there == nullptr || leader_there->speed_mps >= p.desired_speed_mps - rules.blocked_speed_loss_mps)) {
    return v.lane - 1;
  }
  return std::nullopt;
}

bool calls_off_change(const Vehicle& v, const LaneIndex& index, const LaneRules& rules) {
  const LaneChangeState& lc = v.lane_change;
  if (!just_begun(v, rules)) return false;
  const int lanes = index.lanes(v.direction);
  if (lc.to_lane < 0 || lc.to_lane >= lanes || v.lane >= lanes) return false;  // an overtaking: micro's manoeuvre
  const Occupant* leader_there = nullptr;
  return !has_room(v, index, lc.to_lane, 1.0, &leader_there);
}

bool crowds_change(const Vehicle& v, const Vehicle& other, const LaneRules& rules) {
  if (other.id == v.id || other.direction != v.direction || !just_begun(v, rules)) return false;
  const int to = v.lane_change.to_lane;
  if (other.lane != to && other.target_lane() != to) return false;
  const Occupant o = as_occupant(other);
  return other.progress_m() >= v.progress_m() ? !room_behind(v, o, 1.0) : !room_ahead_of(v, o, other.driver.car_following);
}

}  // namespace entourage::meso
