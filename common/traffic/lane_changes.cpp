#include "traffic/lane_changes.hpp"

#include <algorithm>
#include <limits>

#include "traffic/actor_driving.hpp"
#include "traffic/driving.hpp"
#include "traffic/fleet.hpp"

namespace entourage {

namespace {
// A vehicle seeking a gap drops back from the vehicle it lets by to this much below that one's
// speed and holds it (slower only holds its own lane up; back at full speed it never falls behind).
constexpr double kLetBySpeed_mps = 5.0;
// A follower in the target lane that brakes is judged by its speed this far ahead: one braking to
// below the seeker's speed is holding back to let it in.
constexpr double kHoldingBackLookahead_s = 2.0;

bool uses_lane_changes(const Vehicle& v) {
  return v.driver.lane_change == LaneChangeModel::kMobil || v.driver.lane_change == LaneChangeModel::kOvertaking;
}
}  // namespace

// Judged by the changer's parameters alone, a car with a = 1.0 m/s^2 and T = 0.96 s changed in 15 m
// ahead of one whose own model braked at 9 m/s^2 where the estimate said 3.8 (cut-in play, seed 35;
// services/director/README.md, stop 33).
const CarFollowingParams& model_of(VehicleId id, const LaneIndex& index, const CarFollowingParams& judge) {
  const Vehicle* driven = index.drivers() != nullptr ? index.drivers()->find(id) : nullptr;
  return driven != nullptr ? driven->driver.car_following : judge;
}

double follower_accel_mps2(const CarFollowingParams& model, const Occupant& other, const Occupant* leader) {
  if (leader == nullptr) return car_following_accel_mps2(model, other.speed_mps, nullptr);
  const LeaderView lv{gap_between(*leader, other.progress_m, other.length_m), leader->speed_mps, leader->accel_mps2};
  return car_following_accel_mps2(model, other.speed_mps, &lv);
}

LaneChangeOption evaluate_lane_change(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                                      int target) {
  LaneChangeOption opt;
  opt.target_lane = target;
  const auto now = index.neighbours(v.direction, v.lane, v.progress_m(), v.id);
  const auto next = index.neighbours(v.direction, target, v.progress_m(), v.id);
  const Occupant* lead_now = now.leader;
  const Occupant* lead_new = next.leader;
  const Occupant* follow_new = next.follower;
  const Occupant* follow_old = now.follower;
  const Occupant self = as_occupant(v);

  // No overlap with the vehicles beside us in the target lane.
  if (lead_new != nullptr && gap_between(*lead_new, v.progress_m(), v.length_m) <= 0.0) return opt;
  if (follow_new != nullptr && gap_between(self, follow_new->progress_m, follow_new->length_m) <= 0.0) return opt;

  MobilSituation s;
  s.to_right = target < v.lane;
  // The safety criterion first: an unsafe change is refused whatever its incentive.
  s.self_after_mps2 = accel_behind(v, cf, lead_new);
  const CarFollowingParams* new_follower_cf = follow_new != nullptr ? &model_of(follow_new->id, index, cf) : nullptr;
  if (follow_new != nullptr) s.new_follower_after_mps2 = follower_accel_mps2(*new_follower_cf, *follow_new, &self);
  if (!mobil_safe(v.driver.mobil, s.self_after_mps2, s.new_follower_after_mps2)) return opt;
  s.self_now_mps2 = accel_behind(v, cf, lead_now);
  if (follow_new != nullptr) s.new_follower_now_mps2 = follower_accel_mps2(*new_follower_cf, *follow_new, lead_new);
  if (follow_old != nullptr) {
    const CarFollowingParams& old_follower_cf = model_of(follow_old->id, index, cf);
    s.old_follower_now_mps2 = follower_accel_mps2(old_follower_cf, *follow_old, &self);
    s.old_follower_after_mps2 = follower_accel_mps2(old_follower_cf, *follow_old, lead_now);
  }
  const MobilDecision d = mobil_decide(v.driver.mobil, s);
  opt.safe = d.safe;
  opt.advantage_mps2 = d.advantage_mps2;
  return opt;
}

LaneChangeOption evaluate_lane_change(const Vehicle& v, const LaneIndex& index, int target) {
  return evaluate_lane_change(v, v.driver.car_following, index, target);
}

bool lane_allowed(const Vehicle& v, int lane, const DrivingEnvironment& env) {
  if (lane < 0 || lane >= env.lanes(v.direction)) return false;
  if (v.driver.keep_right && lane > v.lane) return false;  // keep-right vehicles only move right
  return !env.ahead().closed_within(v.direction, lane, v.s_m, env.rules().mandatory_lookahead_m);
}

int mandatory_target_lane(const Vehicle& v, const DrivingEnvironment& env) {
  const int lanes = env.lanes(v.direction);
  if (v.lane >= lanes) return -1;  // in the oncoming lane: the overtaking manoeuvre decides
  const int wanted = v.requested_lane >= 0 ? v.requested_lane : director_lane(v);
  if (wanted >= 0 && wanted < lanes && wanted != v.lane) return wanted < v.lane ? v.lane - 1 : v.lane + 1;
  const double lookahead = env.rules().mandatory_lookahead_m;
  if (!env.ahead().closed_within(v.direction, v.lane, v.s_m, lookahead)) return -1;
  for (int target : {v.lane - 1, v.lane + 1}) {  // the right one first
    if (target < 0 || target >= lanes) continue;
    if (!env.ahead().closed_within(v.direction, target, v.s_m, lookahead)) return target;
  }
  return -1;  // every lane is closed: nowhere to go, the closure stops it
}

double gap_seeking_cap_mps2(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                            const LaneChangeState& lc) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  // Vehicles asked only to change lanes (at their own speed): an actor's speed is the plan's.
  const bool clearing = director_lane(v) >= 0 && v.control.speed_mps == kOwnDesiredSpeed_mps;
  if (!clearing || lc.phase != LaneChangePhase::kSignalling || lc.to_lane == v.lane) return kNone;
  const auto next = index.neighbours(v.direction, lc.to_lane, v.progress_m(), v.id);
  const Occupant self = as_occupant(v);
  const double comfort = cf.idm.comfort_decel_mps2;
  // Dropping back from `o`: braking comfortably until a little slower than it, then holding that.
  auto drop_back_from = [&](const Occupant& o) {
    return v.speed_mps <= o.speed_mps - kLetBySpeed_mps ? 0.0 : -comfort;
  };
  // The one beside or just behind in the target lane that leaves no safe gap in front of it is
  // let by, unless it signals towards this vehicle's lane itself (two that each let the other by
  // braked each other to a standstill): the one behind of such a pair gives way.
  if (next.follower != nullptr) {
    const Occupant& f = *next.follower;
    const bool towards_us = f.signal == (v.lane > lc.to_lane ? 1 : -1);
    const bool overlaps = gap_between(self, f.progress_m, f.length_m) <= 0.0;
    // Judged as if it drove at that one's speed: a gap that is only too short because this vehicle
    // is slower is closed by matching speeds behind the leader there, not by letting by (a
    // vehicle that dropped back below the lane's speed found every following gap unsafe).
    Occupant matched = self;
    matched.speed_mps = std::max(self.speed_mps, f.speed_mps);
    const bool unsafe = overlaps || follower_accel_mps2(model_of(f.id, index, cf), f, &matched) <
                                        -v.driver.mobil.safe_decel_mps2;
    // A slower one is holding back to let it in (or will be passed): not let by; nor one that
    // brakes to below its speed within kHoldingBackLookahead_s. Judged by its present speed alone,
    // a follower told to hold back below this vehicle's speed was still the faster one while it
    // braked: this one dropped back from it, that one's target fell with it, and the two braked
    // each other from 24 to 1 m/s, both lanes and the ego behind them (lead vehicle, seed 18).
    const double f_soon_mps = f.speed_mps + std::min(f.accel_mps2, 0.0) * kHoldingBackLookahead_s;
    const bool slower = f_soon_mps < self.speed_mps;
    if (!towards_us && !slower && unsafe) return drop_back_from(f);
  }
  // Else it eases in behind the one ahead there.
  if (next.leader == nullptr) return kNone;
  if (gap_between(*next.leader, v.progress_m(), v.length_m) <= 0.0) return drop_back_from(*next.leader);
  return std::max(accel_behind(v, cf, next.leader), -comfort);
}

LaneChangeState start_moving(const Vehicle& v, int lane, double duration_s) {
  LaneChangeState lc = v.lane_change;
  lc.from_lane = v.lane;
  lc.to_lane = lane;
  lc.phase = LaneChangePhase::kMoving;
  lc.phase_elapsed_s = 0.0;
  lc.duration_s = duration_s;
  return lc;
}

namespace {
LaneChangeState start_signalling(const Vehicle& v, int target) {
  LaneChangeState lc = v.lane_change;
  lc.from_lane = v.lane;
  lc.to_lane = target;
  lc.phase = LaneChangePhase::kSignalling;
  lc.phase_elapsed_s = 0.0;
  lc.duration_s = v.driver.lane_change_duration_s;
  return lc;
}

// MOBIL's best discretionary change, if any.
std::optional<int> discretionary_target(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                                        const DrivingEnvironment& env) {
  LaneChangeOption best;
  bool found = false;
  for (int target : {v.lane - 1, v.lane + 1}) {  // right first: it wins ties
    if (!lane_allowed(v, target, env)) continue;
    const LaneChangeOption opt = evaluate_lane_change(v, cf, index, target);
    if (opt.safe && opt.advantage_mps2 > 0.0 && (!found || opt.advantage_mps2 > best.advantage_mps2)) {
      best = opt;
      found = true;
    }
  }
  if (!found) return std::nullopt;
  return best.target_lane;
}
}  // namespace

LaneChangePlan plan_lane_change(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                                const DrivingEnvironment& env) {
  const DrivingRules& rules = env.rules();
  const double dt_s = env.dt_s();
  LaneChangePlan plan{v.lane_change, false};
  LaneChangeState& lc = plan.state;
  const int mandatory = uses_lane_changes(v) ? mandatory_target_lane(v, env) : -1;
  auto call_off = [&lc] {
    lc.phase = LaneChangePhase::kNone;
    lc.to_lane = lc.from_lane;
  };
  switch (lc.phase) {
    case LaneChangePhase::kNone: {
      lc.since_last_change_s += dt_s;
      if (mandatory >= 0) {  // timing rules do not hold back a change that must happen
        lc = start_signalling(v, mandatory);
        plan.mandatory = true;
        break;
      }
      if (!uses_lane_changes(v) || !chooses_lanes_freely(v) || lc.since_last_change_s < rules.min_interval_s) break;
      if (lc.decision_wait_s > 0.5 * dt_s) {
        lc.decision_wait_s -= dt_s;
        break;
      }
      lc.decision_wait_s = rules.decision_interval_s - dt_s;
      if (const auto target = discretionary_target(v, cf, index, env)) lc = start_signalling(v, *target);
      break;
    }
    case LaneChangePhase::kSignalling: {
      // A vehicle the director moves calls off a change it is no longer asked for: cast as an
      // actor in the lane it was signalling to leave, a car changed out and back, and was 8 s
      // and 20 m late at its start (cut-in, seed 1).
      if (director_lane(v) >= 0 && mandatory != lc.to_lane) {
        call_off();
        break;
      }
      lc.phase_elapsed_s += dt_s;
      if (lc.phase_elapsed_s < rules.signal_s) break;
      const bool must = mandatory == lc.to_lane;
      // The decision was taken when the indicator went on: the change goes as soon as it is safe.
      const LaneChangeOption opt = evaluate_lane_change(v, cf, index, lc.to_lane);
      if (opt.safe) {
        lc.phase = LaneChangePhase::kMoving;
        lc.phase_elapsed_s = 0.0;
        plan.mandatory = must;
      } else if (!must && lc.phase_elapsed_s >= rules.max_signal_wait_s) {
        call_off();  // give up; the interval restarts
        lc.since_last_change_s = 0.0;
      }
      break;
    }
    case LaneChangePhase::kMoving:
      lc.phase_elapsed_s += dt_s;
      break;
  }
  return plan;
}

}  // namespace entourage
