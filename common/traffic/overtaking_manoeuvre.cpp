#include "traffic/overtaking_manoeuvre.hpp"

#include <algorithm>
#include <cmath>

#include "core/random.hpp"
#include "traffic/driving.hpp"
#include "traffic/lane_changes.hpp"

namespace entourage {

namespace {
// A pass overtakes at most this many vehicles of a platoon at once.
constexpr int kMaxPassedVehicles = 3;
// Nobody starts a pass while a vehicle of its own direction uses the oncoming lane this close
// ahead or behind (another overtaker; the time gap for one behind, at its speed).
constexpr double kBusyLaneAhead_m = 150.0;
constexpr double kBusyLaneBehind_s = 3.0;
// ... or an oncoming vehicle beside us, or less than this past us.
constexpr double kBesideProbe_m = 10.0;
// An abort brakes at this multiple of the driver's comfortable deceleration (up to its limit).
constexpr double kAbortBrakeFactor = 2.0;

int oncoming_lane(const Vehicle& v, const DrivingEnvironment& env) { return env.lanes(v.direction); }
int own_lane(const Vehicle& v, const DrivingEnvironment& env) { return env.lanes(v.direction) - 1; }

const Occupant* find(const LaneIndex& index, Direction dir, int lane, VehicleId id) {
  for (const Occupant& o : index.lane(dir, lane)) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

double return_gap_m(const OvertakingParams& p, const Vehicle& v, double speed_mps) {
  return p.return_time_gap_s * speed_mps + v.driver.car_following.idm.min_gap_m;
}

// Is the oncoming lane in use near us: by another vehicle of our direction, or by an oncoming one
// still beside us (the decision model weighs the ones ahead)?
bool oncoming_lane_busy(const Vehicle& v, const LaneIndex& index, int lane) {
  if (const Occupant* o = index.oncoming(v.direction, lane, v.progress_m() - v.length_m - kBesideProbe_m)) {
    const double gap_m = oncoming_gap(*o, v.progress_m(), v.length_m);
    if (gap_m <= 0.0 && gap_m > -(o->length_m + v.length_m + kBesideProbe_m)) return true;
  }
  if (const Occupant* ahead = index.leader(v.direction, lane, v.progress_m(), v.id)) {
    if (gap_between(*ahead, v.progress_m(), v.length_m) < kBusyLaneAhead_m) return true;
  }
  if (const Occupant* behind = index.follower(v.direction, lane, v.progress_m(), v.id)) {
    const Occupant self{v.id, v.progress_m(), v.speed_mps, 0.0, v.length_m};
    if (gap_between(self, behind->progress_m, behind->length_m) < kBusyLaneBehind_s * behind->speed_mps) return true;
  }
  return false;
}

double passing_speed_mps(const OvertakingParams& p, double desired_speed_mps) {
  return p.speed_excess_ratio * desired_speed_mps;
}

// An oncoming vehicle is so close that the drivers brake for each other (the same time to meet,
// or distance, that makes an oncoming driver brake for the overtaker).
bool oncoming_threat(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env) {
  const Occupant* o = index.oncoming(v.direction, oncoming_lane(v, env), v.progress_m());
  if (o == nullptr) return false;
  const double gap_m = oncoming_gap(*o, v.progress_m(), v.length_m);
  return env.rules().oncoming_too_close(gap_m, v.speed_mps + o->speed_mps);
}

OvertakingStep consider_start(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env,
                              double desired_speed_mps) {
  const OvertakingParams& p = env.overtaking();
  OvertakingStep out;
  out.state = v.overtaking;
  out.desired_speed_mps = desired_speed_mps;
  out.rng_state = v.driver.rng_state;
  out.state.next_decision_s = std::max(0.0, out.state.next_decision_s - env.dt_s());
  if (out.state.next_decision_s > 0.0 || v.lane_change.active() || v.lane != own_lane(v, env)) return out;
  const PassChain chain = pass_chain(v, index, p);
  if (chain.first == nullptr || chain.gap_m > p.consider_gap_m || oncoming_lane_busy(v, index, oncoming_lane(v, env))) {
    return out;
  }
  SmallRandom rng(v.driver.rng_state);
  const double draw = rng.uniform();
  out.rng_state = rng.state();
  out.state.next_decision_s = p.decision_interval_s;
  const OvertakingDecision d = decide_overtaking(p, overtaking_situation(v, chain, index, env, desired_speed_mps), draw);
  if (!d.accepted()) return out;
  out.state.phase = OvertakingPhase::kPassing;
  out.state.kind = static_cast<std::uint8_t>(d.kind);
  out.state.overtaken = chain.last->id;
  out.state.elapsed_s = 0.0;
  ++out.state.started;
  out.started = true;
  out.lateral_start = true;
  out.lane_change = start_moving(v, oncoming_lane(v, env), p.lateral_s);
  out.desired_speed_mps = passing_speed_mps(p, desired_speed_mps);
  return out;
}

// The situation during a pass: the overtaken vehicle is the "leader", now beside or behind.
OvertakingSituation pass_situation(const Vehicle& v, const Occupant& overtaken, const LaneIndex& index,
                                   const DrivingEnvironment& env, double desired_speed_mps) {
  PassChain chain;
  chain.first = chain.last = &overtaken;
  chain.count = 1;
  chain.gap_m = gap_between(overtaken, v.progress_m(), v.length_m);
  chain.length_m = overtaken.length_m;
  chain.speed_mps = overtaken.speed_mps;
  if (const Occupant* next = index.leader(v.direction, own_lane(v, env), overtaken.progress_m, overtaken.id)) {
    chain.room_ahead_m = gap_between(*next, overtaken.progress_m, overtaken.length_m);
  }
  return overtaking_situation(v, chain, index, env, desired_speed_mps);
}

OvertakingStep start_return(OvertakingStep out, const Vehicle& v, const DrivingEnvironment& env) {
  out.state.phase = OvertakingPhase::kReturning;
  out.lateral_start = true;
  out.lane_change = start_moving(v, own_lane(v, env), env.overtaking().lateral_s);
  return out;
}

// Still moving out: the driver who sees that the pass can no longer be made pulls back into its
// own lane the way it came, a return from the oncoming lane that starts where the move out is (the
// quintic profile run backwards: same place, the lateral speed turned round, back in the time it
// took to get there). (Reviewed only once out, a pass begun in the step an oncoming vehicle entered
// 62 m ahead went on out for 2 s while both braked, the oncoming one far beyond its limit:
// rural_ego_slow, seed 1, stop 26.)
OvertakingStep call_off_move_out(OvertakingStep out, const Vehicle& v) {
  LaneChangeState& lc = out.lane_change;
  lc = v.lane_change;
  std::swap(lc.from_lane, lc.to_lane);  // commit puts it in from_lane: the oncoming lane it leaves
  lc.phase_elapsed_s = std::max(0.0, lc.duration_s - lc.phase_elapsed_s);
  out.lateral_start = true;
  out.state.phase = OvertakingPhase::kReturning;
  ++out.state.aborted;
  out.aborted = true;
  return out;
}

OvertakingStep start_abort(OvertakingStep out) {
  out.state.phase = OvertakingPhase::kAborting;
  ++out.state.aborted;
  out.aborted = true;
  return out;
}

// Past the overtaken vehicle without the full return gap in front of it (a platoon): cut back in
// if the gap beside allows it; take in the next vehicle only if that pass can still be finished
// with the margin against the oncoming traffic; otherwise abort into a gap behind.
OvertakingStep past_without_room(OvertakingStep out, const Vehicle& v, const Occupant& overtaken,
                                 const LaneIndex& index, const DrivingEnvironment& env,
                                 double desired_speed_mps) {
  if (can_return(v, index, env)) return start_return(out, v, env);
  const Occupant* next = index.leader(v.direction, own_lane(v, env), overtaken.progress_m, overtaken.id);
  if (next == nullptr) return out;
  const PassReview next_review = review_pass(env.overtaking(), pass_situation(v, *next, index, env, desired_speed_mps));
  if (!next_review.safe_to_finish) return start_abort(out);
  out.state.overtaken = next->id;
  out.clear_of_oncoming = true;
  return out;
}

OvertakingStep continue_pass(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env,
                             double desired_speed_mps) {
  const OvertakingParams& p = env.overtaking();
  OvertakingStep out;
  out.state = v.overtaking;
  out.state.elapsed_s += env.dt_s();
  out.rng_state = v.driver.rng_state;
  out.desired_speed_mps = passing_speed_mps(p, desired_speed_mps);
  const Occupant* overtaken = find(index, v.direction, own_lane(v, env), v.overtaking.overtaken);
  if (overtaken == nullptr) {  // gone (left the region, or changed lane): return when there is room
    if (v.lane_change.active()) return out;
    return can_return(v, index, env) ? start_return(out, v, env) : out;
  }
  const OvertakingSituation s = pass_situation(v, *overtaken, index, env, desired_speed_mps);
  const PassReview review = review_pass(p, s);
  out.clear_of_oncoming = review.safe_to_finish;
  if (v.lane_change.active()) {  // still moving out
    return review.action == PassAction::kAbort ? call_off_move_out(out, v) : out;
  }
  switch (review.action) {
    case PassAction::kReturn:  // far enough ahead, and room in front of the overtaken vehicle
      if (can_return(v, index, env)) return start_return(out, v, env);
      return past_without_room(out, v, *overtaken, index, env, desired_speed_mps);
    case PassAction::kAbort:
      return start_abort(out);
    case PassAction::kContinue:
      if (relative_distance_to_pass_m(p, s) <= 0.0) {
        return past_without_room(out, v, *overtaken, index, env, desired_speed_mps);
      }
      return out;
  }
  return out;
}

// The vehicle of the own lane an aborting overtaker drops back behind: from the nearest one whose
// centre is ahead of the overtaker's, backwards, the first with a gap behind it that takes the
// overtaker and both standstill gaps (or the rearmost one).
const Occupant* abort_target(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env) {
  const std::vector<Occupant>& lane = index.lane(v.direction, own_lane(v, env));
  const std::size_t ahead = index.first_not_behind(v.direction, own_lane(v, env), v.progress_m(), v.id);
  if (ahead >= lane.size()) return lane.empty() ? nullptr : &lane.back();
  const double needed_m = v.length_m + 2.0 * v.driver.car_following.idm.min_gap_m;
  for (std::size_t k = ahead; k > 0; --k) {
    const Occupant& front = lane[k];
    const Occupant& rear = lane[k - 1];
    if (gap_between(front, rear.progress_m, rear.length_m) >= needed_m) return &front;
  }
  return &lane.front();
}

// Aborting: brake to drop back behind the abort target, and move back into the own lane as soon as
// the gap beside allows it.
OvertakingStep continue_abort(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env,
                              double desired_speed_mps) {
  OvertakingStep out;
  out.state = v.overtaking;
  out.state.elapsed_s += env.dt_s();
  out.rng_state = v.driver.rng_state;
  out.desired_speed_mps = desired_speed_mps;
  if (can_return(v, index, env)) return start_return(out, v, env);
  const CarFollowingParams cf = local_params(v, env);
  const double brake_mps2 = std::min(v.driver.max_decel_mps2, kAbortBrakeFactor * cf.idm.comfort_decel_mps2);
  const Occupant* target = abort_target(v, index, env);
  if (target == nullptr) return out;
  const double behind_m = gap_between(*target, v.progress_m(), v.length_m);
  if (behind_m < cf.idm.min_gap_m) {
    out.accel_cap_mps2 = -brake_mps2;  // still beside it: drop back
  } else {
    const LeaderView lv{behind_m, target->speed_mps, target->accel_mps2};
    out.accel_cap_mps2 = std::max(-brake_mps2, car_following_accel_mps2(cf, v.speed_mps, &lv));
  }
  return out;
}

// Back in the own lane closer behind the new leader than the car-following model likes (a cut back
// in at a short gap): the model alone would brake far harder than the situation needs.
bool settling(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env) {
  const Occupant* leader = index.leader(v.direction, own_lane(v, env), v.progress_m(), v.id);
  if (leader == nullptr) return false;
  const CarFollowingParams cf = local_params(v, env);
  const LeaderView lv{gap_between(*leader, v.progress_m(), v.length_m), leader->speed_mps, leader->accel_mps2};
  return lv.gap_m >= cf.idm.min_gap_m && car_following_accel_mps2(cf, v.speed_mps, &lv) < -cf.idm.comfort_decel_mps2;
}

OvertakingStep continue_return(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env,
                               double desired_speed_mps) {
  OvertakingStep out;
  out.state = v.overtaking;
  out.state.elapsed_s += env.dt_s();
  out.rng_state = v.driver.rng_state;
  out.desired_speed_mps = desired_speed_mps;
  if (!v.lane_change.active() && v.lane < env.lanes(v.direction)) {
    if (settling(v, index, env)) return out;
    out.state.phase = OvertakingPhase::kNone;  // back in the own lane
    out.state.next_decision_s = env.overtaking().decision_interval_s;
  } else if (v.overtaking.phase == OvertakingPhase::kReturning && v.lane >= env.lanes(v.direction)) {
    out.desired_speed_mps = passing_speed_mps(env.overtaking(), desired_speed_mps);  // finishing the pass
  }
  return out;
}
}  // namespace

bool can_return(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env) {
  const bool threat = oncoming_threat(v, index, env);
  const double leader_limit_mps2 = threat ? v.driver.max_decel_mps2 : env.overtaking().return_decel_mps2;
  const double follower_limit_mps2 =
      threat ? std::min(v.driver.max_decel_mps2, env.overtaking().follower_max_decel_mps2)
             : env.overtaking().return_decel_mps2;
  const double min_gap_m = v.driver.car_following.idm.min_gap_m;
  const LaneIndex::Neighbours n = index.neighbours(v.direction, own_lane(v, env), v.progress_m(), v.id);
  // Back in the lane it brakes for its new leader as the leader does (driving.cpp, the cut-in
  // floor): the follower there is judged against that braking, not against a car holding its speed
  // (a car that cut back in behind one braking for a queue was otherwise run into by its follower).
  double own_brake_mps2 = std::max(0.0, -v.accel_mps2);
  if (n.leader != nullptr) {
    const double gap_m = gap_between(*n.leader, v.progress_m(), v.length_m);
    const double needed = keep_gap_behind_braking_mps2(gap_m, min_gap_m, v.speed_mps, n.leader->speed_mps,
                                                       std::max(0.0, -n.leader->accel_mps2));
    if (needed > leader_limit_mps2) return false;
    own_brake_mps2 = std::max(own_brake_mps2, needed);
  }
  if (n.follower != nullptr) {
    const Occupant self{v.id, v.progress_m(), v.speed_mps, 0.0, v.length_m};
    const double gap_m = gap_between(self, n.follower->progress_m, n.follower->length_m);
    if (keep_gap_behind_braking_mps2(gap_m, min_gap_m, n.follower->speed_mps, v.speed_mps, own_brake_mps2) >
        follower_limit_mps2) {
      return false;
    }
  }
  return true;
}

bool overtakes(const Vehicle& v, const DrivingEnvironment& env) {
  return env.two_way() && v.driver.lane_change == LaneChangeModel::kOvertaking;
}

PassChain pass_chain(const Vehicle& v, const LaneIndex& index, const OvertakingParams& p) {
  PassChain c;
  const auto& lane = index.lane(v.direction, v.lane);
  const Occupant probe{v.id, v.progress_m(), 0.0, 0.0, 0.0};
  auto it = std::upper_bound(lane.begin(), lane.end(), probe, [](const Occupant& a, const Occupant& b) {
    return a.progress_m < b.progress_m || (a.progress_m == b.progress_m && a.id < b.id);
  });
  for (; it != lane.end(); ++it) {
    if (it->id == v.id) continue;
    if (c.first == nullptr) {
      c.first = c.last = &*it;
      c.count = 1;
      c.gap_m = gap_between(*it, v.progress_m(), v.length_m);
      c.speed_mps = it->speed_mps;
      continue;
    }
    const double room = gap_between(*it, c.last->progress_m, c.last->length_m);
    const double needed = v.length_m + return_gap_m(p, v, c.speed_mps);
    if (room >= needed || c.count >= kMaxPassedVehicles) {
      c.room_ahead_m = room;
      break;
    }
    c.last = &*it;
    ++c.count;
    c.speed_mps = std::max(c.speed_mps, it->speed_mps);
  }
  if (c.first != nullptr) {
    c.length_m = (c.last->progress_m + 0.5 * c.last->length_m) - (c.first->progress_m - 0.5 * c.first->length_m);
  }
  return c;
}

OvertakingSituation overtaking_situation(const Vehicle& v, const PassChain& chain, const LaneIndex& index,
                                         const DrivingEnvironment& env, double desired_speed_mps) {
  OvertakingSituation s;
  const IdmParams& idm = v.driver.car_following.idm;
  s.speed_mps = v.speed_mps;
  s.desired_speed_mps = desired_speed_mps;
  s.max_accel_mps2 = idm.max_accel_mps2;
  s.length_m = v.length_m;
  s.min_gap_m = idm.min_gap_m;
  s.leader_gap_m = chain.gap_m;
  s.leader_speed_mps = chain.speed_mps;
  s.leader_length_m = chain.length_m;
  s.room_ahead_of_leader_m = chain.room_ahead_m;
  // The nearest oncoming vehicle in the lane of the pass, or in the own lane: one passing there
  // moves back into its lane, the lane of the pass, before we would meet it. (Two passes started
  // towards each other, each in the other's lane, blocked each other's way back, and the aborting
  // drivers stopped face to face.)
  for (const int lane : {env.lanes(v.direction), own_lane(v, env)}) {
    const Occupant* o = index.oncoming(v.direction, lane, v.progress_m());
    if (o == nullptr) continue;
    const double distance_m = std::max(0.0, oncoming_gap(*o, v.progress_m(), v.length_m));
    if (distance_m < s.oncoming_distance_m) {
      s.oncoming_distance_m = distance_m;
      s.oncoming_speed_mps = o->speed_mps;
    }
  }
  s.sight_distance_m = env.ahead().sight_distance_m(v.direction, v.s_m);
  s.restriction_free_m = env.ahead().restriction_free_m(v.direction, v.s_m);
  return s;
}

OvertakingStep overtaking_step(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env,
                               double desired_speed_mps) {
  switch (v.overtaking.phase) {
    case OvertakingPhase::kNone:
      if (!overtakes(v, env)) break;
      return consider_start(v, index, env, desired_speed_mps);
    case OvertakingPhase::kPassing:
      return continue_pass(v, index, env, desired_speed_mps);
    case OvertakingPhase::kAborting:
      return continue_abort(v, index, env, desired_speed_mps);
    case OvertakingPhase::kReturning:
      return continue_return(v, index, env, desired_speed_mps);
  }
  OvertakingStep out;
  out.state = v.overtaking;
  out.desired_speed_mps = desired_speed_mps;
  out.rng_state = v.driver.rng_state;
  return out;
}

}  // namespace entourage
