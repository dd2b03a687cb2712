#include "traffic/driving.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "traffic/actor_driving.hpp"
#include "traffic/lane_changes.hpp"
#include "traffic/overtaking_manoeuvre.hpp"

namespace entourage {

namespace {
// The emergency regime stops a vehicle at the latest this far behind what it approaches.
constexpr double kEmergencyStandstillGap_m = 0.5;
// Leaders the HDM can anticipate at most (its n_a is capped here).
constexpr std::size_t kMaxAnticipated = 8;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A controlled actor's car following runs at this desired speed: only its interaction with the
// vehicle ahead limits what the script asks (actor_driving.hpp).
constexpr double kScriptedCarFollowingSpeed_mps = 100.0;

LeaderView view_of(const Occupant& leader, const Vehicle& v) {
  return LeaderView{gap_between(leader, v.progress_m(), v.length_m), leader.speed_mps, leader.accel_mps2};
}

// The lanes `v` occupies: its own, and the one it moves into while it moves sideways.
struct Occupied {
  std::array<int, 2> lanes{};
  int count = 1;
};
Occupied occupied(const Vehicle& v) {
  Occupied o;
  o.lanes[0] = v.lane;
  if (v.lane_change.moving() && v.lane_change.to_lane != v.lane) {
    o.lanes[1] = v.lane_change.to_lane;
    o.count = 2;
  }
  return o;
}

// Up to `max` nearest leaders of v in `lane`, nearest first.
std::size_t leaders_in(const Vehicle& v, const LaneIndex& index, int lane, LeaderView* out, std::size_t max) {
  const auto& l = index.lane(v.direction, lane);
  auto it = l.begin() + static_cast<std::ptrdiff_t>(index.first_not_behind(v.direction, lane, v.progress_m(), v.id));
  std::size_t n = 0;
  for (; it != l.end() && n < max; ++it) {
    if (it->id != v.id) out[n++] = view_of(*it, v);
  }
  return n;
}

// Something standing in the way that is not a vehicle of the own direction: the start of a closure
// of the lane, or the point where the driver would meet an opposite-direction vehicle in its lane.
struct Obstacle {
  double gap_m = kInfinity;
  double closing_mps = 0.0;  // how fast the driver approaches it (its own speed: it stands)
};

// Does an overtaker in the oncoming lane leave the oncoming vehicle there to its pass review
// (overtaking_manoeuvre.hpp, OvertakingStep::clear_of_oncoming)? Passing, while the review finds
// the rest of the pass can be finished in time; moving back in, while it is out of the lane before
// they would meet. Braking for it all the same undid passes the review had found safe: the
// overtaker slowed beside the vehicle it passed until the pass failed, the oncoming driver braking
// as well, and then cut back in at a crawl in front of its former follower, which ran into it.
bool leaves_oncoming_to_pass_review(const Vehicle& v, int lane, const DrivingEnvironment& env, bool clear_of_oncoming,
                                    double gap_m, double closing_mps) {
  if (lane < env.lanes(v.direction)) return false;
  switch (v.overtaking.phase) {
    case OvertakingPhase::kPassing:
      return clear_of_oncoming;
    case OvertakingPhase::kReturning:
      return gap_m > closing_mps * v.lane_change.moving_left_s();
    default:
      return false;
  }
}

}  // namespace

bool out_of_the_way_before_meeting(const Vehicle& v, const Occupant& oncoming, int lane, double gap_m,
                                   double closing_mps, const DrivingEnvironment& env) {
  // Its return takes at most the overtaking's lateral time (a pass called off on the way out less).
  return lane < env.lanes(v.direction) && oncoming.leaving && gap_m > closing_mps * env.overtaking().lateral_s;
}

namespace {
Obstacle obstacle_in(const Vehicle& v, const LaneIndex& index, int lane, const DrivingEnvironment& env,
                     bool clear_of_oncoming) {
  Obstacle ob;
  const DrivingRules& rules = env.rules();
  if (lane < env.lanes(v.direction)) {
    const double to_closure = env.ahead().distance_to_closure_m(v.direction, lane, v.s_m) - 0.5 * v.length_m;
    if (to_closure < rules.mandatory_lookahead_m) ob.gap_m = std::max(0.0, to_closure);
  }
  if (env.two_way()) {
    if (const Occupant* o = index.oncoming(v.direction, lane, v.progress_m())) {
      const double gap = std::max(0.0, oncoming_gap(*o, v.progress_m(), v.length_m));
      const double closing = v.speed_mps + o->speed_mps;
      // Both drivers stop short of the meeting point: each has half the gap.
      // Also when both stand: one that stopped facing the other must not creep towards it.
      if (rules.oncoming_too_close(gap, closing) &&
          !leaves_oncoming_to_pass_review(v, lane, env, clear_of_oncoming, gap, closing) &&
          !out_of_the_way_before_meeting(v, *o, lane, gap, closing, env)) {
        ob.gap_m = std::min(ob.gap_m, 0.5 * gap);
      }
    }
  }
  ob.closing_mps = v.speed_mps;
  return ob;
}

struct Longitudinal {
  double decided_mps2 = 0.0;  // the model's acceleration now (HDM: before the reaction delay)
  double applied_mps2 = 0.0;
  bool emergency = false;
};

double emergency_limit(const Vehicle& v, const CarFollowingParams& cf, double gap_m, double closing_mps, double a,
                       bool* emergency) {
  const double needed = stopping_decel_mps2(gap_m, closing_mps);
  if (needed > cf.idm.comfort_decel_mps2 && -needed < a) {
    *emergency = true;
    return -std::min(needed, v.driver.max_decel_mps2);
  }
  return a;
}

// What keeping the standstill gap behind `leader` takes, the leader keeping its deceleration.
double cut_in_needed_mps2(const Vehicle& v, const CarFollowingParams& cf, const LeaderView& leader) {
  return keep_gap_behind_braking_mps2(leader.gap_m, cf.idm.min_gap_m, v.speed_mps, leader.speed_mps,
                                      std::max(0.0, -leader.accel_mps2));
}

// An overtaker cutting back in behind a leader at a short gap (and settling behind it afterwards)
// brakes as the kinematics need, at least comfortably, instead of the car-following model's far
// harder reaction to a gap below its desired one: the constant-acceleration heuristic of Kesting,
// Treiber & Helbing (2010) in its simplest form, the leader keeping its deceleration: the gap kept
// at the leader's speed, and, while the leader brakes, a stop behind the point where it stops.
// (Judged at the leader's speed alone, a car cutting back in behind one braking for a queue braked
// at 2 m/s^2 while 3 were needed, and they touched.) Inside the standstill gap there is no floor.
// `needed_mps2`: cut_in_needed_mps2.
double cut_in_floor_mps2(const CarFollowingParams& cf, double needed_mps2) {
  return -std::max(cf.idm.comfort_decel_mps2, needed_mps2);
}

// Moving out to pass, the overtaker is clear of the vehicle ahead in its own lane once it is in the
// other lane: it does not follow it meanwhile (the car-following model would hold it at its desired
// gap, and a pass planned to gain from its start lost the whole lateral move), unless at its free
// acceleration it would come within its standstill gap before the move is over.
bool clears_moving_out(const Vehicle& v, const CarFollowingParams& cf, int lane, const LeaderView& leader) {
  const LaneChangeState& lc = v.lane_change;
  if (v.overtaking.phase != OvertakingPhase::kPassing || !lc.moving() || lane != lc.from_lane) return false;
  const double left_s = lc.moving_left_s();
  const double rel_accel = std::max(0.0, car_following_accel_mps2(cf, v.speed_mps, nullptr) - leader.accel_mps2);
  const double gain_m = (v.speed_mps - leader.speed_mps) * left_s + 0.5 * rel_accel * left_s * left_s;
  return gain_m < leader.gap_m - cf.idm.min_gap_m;
}

Longitudinal longitudinal(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                          const DrivingEnvironment& env, bool clear_of_oncoming) {
  const bool hdm = cf.human_driver;
  const std::size_t anticipate =
      hdm ? std::min<std::size_t>(kMaxAnticipated, static_cast<std::size_t>(std::max(1, cf.hdm.anticipated_leaders))) : 1;
  std::array<LeaderView, kMaxAnticipated> views;  // filled up to the count leaders_in returns
  std::array<std::size_t, 2> counts{};
  std::array<LeaderView, 2> nearest{};
  std::array<Obstacle, 2> obstacles{};
  const Occupied occ = occupied(v);
  const int returning_to = v.overtaking.phase == OvertakingPhase::kReturning ? env.lanes(v.direction) - 1 : -1;
  double decided = kInfinity;
  double cut_in_needed = 0.0;
  for (int i = 0; i < occ.count; ++i) {
    const int lane = occ.lanes[static_cast<std::size_t>(i)];
    std::size_t n = leaders_in(v, index, lane, views.data(), anticipate);
    if (n > 0 && clears_moving_out(v, cf, lane, views[0])) n = 0;
    counts[static_cast<std::size_t>(i)] = n;
    if (n > 0) nearest[static_cast<std::size_t>(i)] = views[0];
    double a = hdm ? hdm_instant_accel_mps2(cf, cf.hdm, v.hdm_errors, v.speed_mps, views.data(), n)
                         : car_following_accel_mps2(cf, v.speed_mps, n > 0 ? views.data() : nullptr);
    if (n > 0 && lane == returning_to) {
      cut_in_needed = cut_in_needed_mps2(v, cf, views[0]);
      a = std::max(a, cut_in_floor_mps2(cf, cut_in_needed));
    }
    decided = std::min(decided, a);
    const Obstacle ob = obstacle_in(v, index, lane, env, clear_of_oncoming);
    obstacles[static_cast<std::size_t>(i)] = ob;
    if (std::isfinite(ob.gap_m)) {
      const LeaderView standing{ob.gap_m, 0.0, 0.0};
      decided = std::min(decided, car_following_accel_mps2(cf, v.speed_mps, &standing));
    }
  }
  // A slower section ahead (a lower limit, a curve): brake so as to arrive at its speed.
  const double approach = env.speeds().approach_decel_needed_mps2(v.direction, v.s_m, v.speed_mps,
                                                                  v.driver.desired_speed_mps(), v.driver.basic_median_mps());
  if (approach >= env.speeds().params().approach_decel_mps2) decided = std::min(decided, -approach);
  Longitudinal out;
  out.decided_mps2 = decided;
  double a = hdm ? v.hdm_memory.delayed(decided, cf.hdm.reaction_time_s, env.dt_s()) : decided;
  // Cutting back in, the driver brakes at once as hard as keeping its standstill gap behind the new
  // leader needs: the return was planned with that braking (can_return), it is no reaction that
  // lags. (With the reaction delay, a car that cut back in 9.6 m behind a truck at 7.5 m/s closing
  // braked at 3.0 m/s^2 where 3.6 were needed and came within 1.6 m of it: rural_ego_slow, seed 1,
  // stop 26.)
  if (cut_in_needed > 0.0) a = std::min(a, -cut_in_needed);
  for (int i = 0; i < occ.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (counts[k] > 0) {
      a = emergency_limit(v, cf, nearest[k].gap_m, v.speed_mps - nearest[k].speed_mps, a, &out.emergency);
    }
    if (std::isfinite(obstacles[k].gap_m)) {
      a = emergency_limit(v, cf, obstacles[k].gap_m, obstacles[k].closing_mps, a, &out.emergency);
    }
  }
  out.applied_mps2 = std::max(a, -v.driver.max_decel_mps2);
  return out;
}

LaneChangeState advance_lateral(const Vehicle& v, double dt_s) {
  LaneChangeState lc = v.lane_change;
  if (lc.moving()) lc.phase_elapsed_s += dt_s;
  return lc;
}

void finish_lane_change_if_done(LaneChangeState& lc, int& lane) {
  if (lc.moving() && lc.phase_elapsed_s >= lc.duration_s) {
    lane = lc.to_lane;
    lc.from_lane = lc.to_lane;
    lc.phase = LaneChangePhase::kNone;
    lc.phase_elapsed_s = 0.0;
    lc.since_last_change_s = 0.0;
  }
}
}  // namespace

CarFollowingParams local_params(const Vehicle& v, const DrivingEnvironment& env) {
  CarFollowingParams cf = v.driver.car_following;
  cf.idm.desired_speed_mps = actor_desired_speed_mps(
      v, env.speeds().desired_speed_mps(v.direction, v.s_m, v.driver.desired_speed_mps(), v.driver.basic_median_mps()));
  return cf;
}

const Occupant* leader_of(const Vehicle& v, const LaneIndex& index, int lane) {
  return index.leader(v.direction, lane, v.progress_m(), v.id);
}

double stopping_decel_mps2(double gap_m, double closing_mps) {
  if (closing_mps <= 0.0) return 0.0;
  const double room = gap_m - kEmergencyStandstillGap_m;
  return room > 0.0 ? closing_mps * closing_mps / (2.0 * room) : kInfinity;
}

double keep_gap_decel_mps2(double gap_m, double min_gap_m, double closing_mps) {
  const double room_m = gap_m - min_gap_m;
  if (room_m < 0.0) return kInfinity;
  if (closing_mps <= 0.0) return 0.0;
  return room_m > 0.0 ? closing_mps * closing_mps / (2.0 * room_m) : kInfinity;
}

double keep_gap_behind_braking_mps2(double gap_m, double min_gap_m, double follower_mps, double leader_mps,
                                    double leader_brake_mps2) {
  const double closing = keep_gap_decel_mps2(gap_m, min_gap_m, follower_mps - leader_mps);
  if (leader_brake_mps2 <= 0.0 || !std::isfinite(closing)) return closing;
  const double room_m = gap_m - min_gap_m + leader_mps * leader_mps / (2.0 * leader_brake_mps2);
  return std::max(closing, follower_mps * follower_mps / (2.0 * room_m));
}

double accel_behind(const Vehicle& v, const CarFollowingParams& cf, const Occupant* leader, bool* emergency) {
  if (leader == nullptr) return car_following_accel_mps2(cf, v.speed_mps, nullptr);
  const LeaderView lv = view_of(*leader, v);
  double a = car_following_accel_mps2(cf, v.speed_mps, &lv);
  bool em = false;
  a = emergency_limit(v, cf, lv.gap_m, v.speed_mps - leader->speed_mps, a, &em);
  if (em && emergency != nullptr) *emergency = true;
  return std::max(a, -v.driver.max_decel_mps2);
}

double accel_behind(const Vehicle& v, const Occupant* leader, bool* emergency) {
  return accel_behind(v, v.driver.car_following, leader, emergency);
}

Decision decide(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env) {
  Decision d;
  d.rng_state = v.driver.rng_state;
  d.overtaking = v.overtaking;
  CarFollowingParams cf = local_params(v, env);

  const bool scripted = v.control.mode == ControlMode::kControlled;
  if (scripted) cf.idm.desired_speed_mps = kScriptedCarFollowingSpeed_mps;  // the script sets the speed

  double accel_cap = kInfinity;
  bool clear_of_oncoming = false;
  bool lateral_decided = false;
  if ((overtakes(v, env) && chooses_lanes_freely(v)) || v.overtaking.active()) {
    const OvertakingStep ot = overtaking_step(v, index, env, cf.idm.desired_speed_mps);
    d.overtaking = ot.state;
    d.rng_state = ot.rng_state;
    cf.idm.desired_speed_mps = ot.desired_speed_mps;
    accel_cap = ot.accel_cap_mps2;
    clear_of_oncoming = ot.clear_of_oncoming;
    if (ot.lateral_start) {
      d.lane_change = ot.lane_change;
      lateral_decided = true;
    } else if (v.overtaking.active() || ot.state.active()) {
      d.lane_change = advance_lateral(v, env.dt_s());
      lateral_decided = true;
    }
  }
  if (!lateral_decided) {
    if (auto lc = scripted_lane_change(v, index, env)) {
      d.lane_change = *lc;
      lateral_decided = true;
    }
  }
  if (!lateral_decided) {
    const LaneChangePlan plan = plan_lane_change(v, cf, index, env);
    d.lane_change = plan.state;
    d.mandatory_change = plan.mandatory;
  }

  const double gap_seeking_mps2 = gap_seeking_cap_mps2(v, cf, index, d.lane_change);
  // Easing down to a lower speed the director asks for: car following as if at the present speed,
  // the free-road slowing bounded apart (eases_down).
  double easing_mps2 = kInfinity;
  if (eases_down(v, cf.idm.desired_speed_mps)) {
    easing_mps2 = easing_accel_mps2(cf, v.speed_mps);
    cf.idm.desired_speed_mps = v.speed_mps;
  }
  const Longitudinal lon = longitudinal(v, cf, index, env, clear_of_oncoming);
  d.hdm_decided_mps2 = lon.decided_mps2;
  double a = std::min({lon.applied_mps2, accel_cap, gap_seeking_mps2, easing_mps2});
  if (scripted) a = scripted_accel_mps2(v, a, cf.idm.max_accel_mps2, env.dt_s());
  d.accel_mps2 = std::max(limit_rise_mps2(v, a, env.dt_s()), -v.driver.max_decel_mps2);
  d.emergency = lon.emergency;
  return d;
}

void commit(Vehicle& v, const Decision& d, double dt_s) {
  v.lane_change = d.lane_change;
  // A vehicle is in the lane its lateral movement leaves (vehicle.hpp): the same lane for every
  // movement but a pass called off on its way out, which leaves the oncoming lane.
  if (v.lane_change.moving()) v.lane = v.lane_change.from_lane;
  v.overtaking = d.overtaking;
  v.driver.rng_state = d.rng_state;
  if (v.driver.car_following.human_driver) {
    v.hdm_memory.push(d.hdm_decided_mps2);
    SmallRandom rng(v.driver.rng_state);
    advance_hdm_errors(v.hdm_errors, v.driver.car_following.hdm, dt_s, rng);
    v.driver.rng_state = rng.state();
  }
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
  finish_lane_change_if_done(v.lane_change, v.lane);
}

void continue_lane_change(LaneChangeState& lc, int& lane, double dt_s) {
  lc.since_last_change_s += dt_s;
  if (lc.phase == LaneChangePhase::kSignalling) {
    lc.phase = LaneChangePhase::kNone;
    lc.to_lane = lc.from_lane = lane;
  } else if (lc.moving()) {
    lc.phase_elapsed_s += dt_s;
    finish_lane_change_if_done(lc, lane);
  }
}

void continue_lane_change(Vehicle& v, double dt_s) { continue_lane_change(v.lane_change, v.lane, dt_s); }

const Occupant* nearest_leader(const Vehicle& v, const LaneIndex& index) {
  const Occupant* best = leader_of(v, index, v.lane);
  if (v.lane_change.moving()) {
    const Occupant* other = leader_of(v, index, v.lane_change.to_lane);
    if (other != nullptr && (best == nullptr || other->progress_m < best->progress_m)) best = other;
  }
  return best;
}

}  // namespace entourage
