#include "behaviour/overtaking.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace entourage {

namespace {

// The gap kept behind the overtaker, ahead of the overtaken vehicle, once back in the own lane:
// return_time_gap_s at the overtaken vehicle's speed plus the overtaker's standstill gap.
double return_gap_m(const OvertakingParams& p, const OvertakingSituation& s) {
  return p.return_time_gap_s * s.leader_speed_mps + s.min_gap_m;
}

// Room the overtaker needs in front of the overtaken vehicle to move back into its lane: its own
// length behind the return gap (the gap to the vehicle ahead of that room is not required).
bool room_to_return(const OvertakingParams& p, const OvertakingSituation& s) {
  return s.room_ahead_of_leader_m >= s.length_m + return_gap_m(p, s);
}

// The planned motion of the overtaker: constant acceleration from v0 up to the passing speed,
// reached at t_accel_end_s, then that speed held.
struct PassMotion {
  double v0_mps;
  double accel_mps2;
  double passing_speed_mps;
  double t_accel_end_s;

  double speed_mps(double t_s) const { return v0_mps + accel_mps2 * std::min(t_s, t_accel_end_s); }

  double distance_m(double t_s) const {
    const double t1 = std::min(t_s, t_accel_end_s);
    const double accelerating = v0_mps * t1 + 0.5 * accel_mps2 * t1 * t1;
    return accelerating + passing_speed_mps * std::max(0.0, t_s - t_accel_end_s);
  }
};

// Positive root t of (a/2) t^2 + b t - d = 0 for a > 0, d > 0 (there is exactly one), written in
// the form that does not cancel for either sign of b.
double positive_root_s(double half_a, double b, double d) {
  const double root = std::sqrt(b * b + 4.0 * half_a * d);
  return b >= 0.0 ? 2.0 * d / (b + root) : (root - b) / (2.0 * half_a);
}

// Time at which the overtaker has gained `relative_distance_m` on a leader at constant speed.
// The relative gain is g(t) = (v0 - v_l) t + a t^2 / 2 while accelerating (it may first go
// negative when the overtaker starts slower than the leader; g is convex with g(0) = 0, so the
// first time it reaches d > 0 is the positive root), then grows at (v_pass - v_l) > 0.
double time_to_gain_s(const PassMotion& m, double leader_speed_mps, double relative_distance_m) {
  if (relative_distance_m <= 0.0) return 0.0;
  const double closing_mps = m.v0_mps - leader_speed_mps;
  const double t1 = m.t_accel_end_s;
  const double gain_at_t1_m = closing_mps * t1 + 0.5 * m.accel_mps2 * t1 * t1;
  if (t1 > 0.0 && gain_at_t1_m >= relative_distance_m) {
    return positive_root_s(0.5 * m.accel_mps2, closing_mps, relative_distance_m);
  }
  return t1 + (relative_distance_m - gain_at_t1_m) / (m.passing_speed_mps - leader_speed_mps);
}

// The room a plan needs in the oncoming lane with `margin_s` of margin after its end.
double gap_needed_m(const PassPlan& plan, double oncoming_speed_mps, double margin_s) {
  return plan.distance_m + oncoming_speed_mps * (plan.duration_s + margin_s);
}

// Committed: the overtaker's rear is ahead of the overtaken vehicle's front minus commit_share of
// its length. With the overtaker's front at 0, its rear is at -length_m, the leader's rear at
// leader_gap_m and its front at leader_gap_m + leader_length_m, so the condition
//   -length_m >= leader_gap_m + leader_length_m - commit_share * leader_length_m
// reads leader_gap_m <= -(length_m + (1 - commit_share) * leader_length_m).
bool committed(const OvertakingParams& p, const OvertakingSituation& s) {
  return s.leader_gap_m <= -(s.length_m + (1.0 - p.commit_share) * s.leader_length_m);
}

bool nothing_to_overtake(const OvertakingParams& p, const OvertakingSituation& s) {
  return s.leader_gap_m > p.consider_gap_m || s.leader_speed_mps >= s.desired_speed_mps;
}

}  // namespace

double AcceptanceCurve::probability(double gap_m) const {
  // An empty curve, or an undefined gap, accepts nothing.
  if (points.empty() || std::isnan(gap_m)) return 0.0;
  double prob = 0.0;
  if (gap_m <= points.front().first) {
    prob = points.front().second;
  } else if (gap_m >= points.back().first) {
    prob = points.back().second;  // also for an infinite gap
  } else {
    // First point strictly beyond the gap: its predecessor is at or before it, so x1 > x0 even
    // with repeated gaps (a step), and the division is safe.
    const auto upper = std::upper_bound(points.begin(), points.end(), gap_m,
                                        [](double g, const std::pair<double, double>& pt) { return g < pt.first; });
    const auto lower = std::prev(upper);
    const double share = (gap_m - lower->first) / (upper->first - lower->first);
    prob = lower->second + share * (upper->second - lower->second);
  }
  return std::clamp(prob, 0.0, 1.0);
}

double relative_distance_to_pass_m(const OvertakingParams& p, const OvertakingSituation& s) {
  return s.leader_gap_m + s.leader_length_m + s.length_m + return_gap_m(p, s);
}

// The passing speed is speed_excess_ratio * desired speed, but never below the current speed (an
// overtaker does not slow down to pass). Without acceleration (accel_share * max_accel <= 0) the
// current speed is held and is the passing speed. Feasible iff the passing speed beats the
// leader's by min_speed_gain_mps (and strictly). The lateral move out overlaps the gain; the move
// back takes lateral_s after it, at the speed reached at the end of the gain. duration_s and
// distance_m stay 0 for an infeasible plan; relative_distance_m is always filled.
PassPlan plan_pass(const OvertakingParams& p, const OvertakingSituation& s) {
  PassPlan plan;
  plan.relative_distance_m = relative_distance_to_pass_m(p, s);
  const double accel_mps2 = p.accel_share * s.max_accel_mps2;
  const bool can_accelerate = accel_mps2 > 0.0;
  const double target_mps = p.speed_excess_ratio * s.desired_speed_mps;
  plan.passing_speed_mps = can_accelerate ? std::max(s.speed_mps, target_mps) : s.speed_mps;
  const double speed_gain_mps = plan.passing_speed_mps - s.leader_speed_mps;
  plan.feasible = speed_gain_mps >= p.min_speed_gain_mps && speed_gain_mps > 0.0;
  if (!plan.feasible) return plan;

  PassMotion motion{s.speed_mps, can_accelerate ? accel_mps2 : 0.0, plan.passing_speed_mps, 0.0};
  if (can_accelerate) motion.t_accel_end_s = (plan.passing_speed_mps - s.speed_mps) / accel_mps2;
  const double t_gain_s = time_to_gain_s(motion, s.leader_speed_mps, plan.relative_distance_m);
  plan.duration_s = t_gain_s + p.lateral_s;
  plan.distance_m = motion.distance_m(t_gain_s) + motion.speed_mps(t_gain_s) * p.lateral_s;
  return plan;
}

double required_gap_m(const OvertakingParams& p, const PassPlan& plan, double oncoming_speed_mps) {
  return gap_needed_m(plan, oncoming_speed_mps, p.safety_margin_s);
}

OvertakingKind classify(const OvertakingParams& p, const OvertakingSituation& s) {
  return s.speed_mps - s.leader_speed_mps >= p.flying_min_closing_mps ? OvertakingKind::kFlying
                                                                      : OvertakingKind::kAccelerated;
}

// The header's four questions, evaluated as: restrictions, capability, gap, willingness. The gap
// needs a feasible plan, so capability comes before it. kind and available_gap_m are filled in
// every verdict, the plan from kRestricted on, the probability only when willingness is asked.
OvertakingDecision decide_overtaking(const OvertakingParams& p, const OvertakingSituation& s, double uniform_draw) {
  OvertakingDecision d;
  d.kind = classify(p, s);
  d.available_gap_m = std::min(s.oncoming_distance_m, s.sight_distance_m);
  if (nothing_to_overtake(p, s)) {
    d.verdict = OvertakingVerdict::kNoLeader;
    return d;
  }
  d.plan = plan_pass(p, s);

  // 1. Restrictions: an infeasible plan has no distance; its relative distance is a lower bound.
  const double road_needed_m = d.plan.feasible ? d.plan.distance_m : d.plan.relative_distance_m;
  if (road_needed_m > s.restriction_free_m) {
    d.verdict = OvertakingVerdict::kRestricted;
    return d;
  }
  // 3. Capability: a passing speed clearly above the leader's, within max_distance_m of road.
  if (!d.plan.feasible || d.plan.distance_m > p.max_distance_m) {
    d.verdict = OvertakingVerdict::kNotCapable;
    return d;
  }
  // 2. Gap: the seen oncoming vehicle, one hidden just beyond the sight distance, and room to
  // move back in front of the overtaken vehicle.
  const bool oncoming_too_close = required_gap_m(p, d.plan, s.oncoming_speed_mps) > s.oncoming_distance_m;
  const bool sight_too_short = required_gap_m(p, d.plan, p.hidden_oncoming_speed_mps) > s.sight_distance_m;
  if (oncoming_too_close || sight_too_short || !room_to_return(p, s)) {
    d.verdict = OvertakingVerdict::kGapTooShort;
    return d;
  }
  // 4. Willingness: a fresh draw against the curve of this kind of overtaking.
  const AcceptanceCurve& curve = d.kind == OvertakingKind::kFlying ? p.flying : p.accelerated;
  d.acceptance_probability = curve.probability(d.available_gap_m);
  d.verdict = uniform_draw < d.acceptance_probability ? OvertakingVerdict::kAccepted : OvertakingVerdict::kUnwilling;
  return d;
}

// Return when far enough ahead and there is room; otherwise continue when the rest of the pass
// (plan_pass from here) still fits before the oncoming vehicle with abort_margin_s, or when the
// overtaker is committed (finishing is the lesser evil, also when the rest is infeasible); abort
// otherwise. Far enough ahead but without room, the same rule applies (there the overtaker is
// always committed for commit_share <= 1, so it keeps passing): what next is the caller's choice.
PassReview review_pass(const OvertakingParams& p, const OvertakingSituation& s) {
  PassReview r;
  r.remaining = plan_pass(p, s);
  if (relative_distance_to_pass_m(p, s) <= 0.0 && room_to_return(p, s)) {
    r.action = PassAction::kReturn;
    r.safe_to_finish = true;
    return r;
  }
  r.safe_to_finish =
      r.remaining.feasible && gap_needed_m(r.remaining, s.oncoming_speed_mps, p.abort_margin_s) <= s.oncoming_distance_m;
  r.action = r.safe_to_finish || committed(p, s) ? PassAction::kContinue : PassAction::kAbort;
  return r;
}

}  // namespace entourage
