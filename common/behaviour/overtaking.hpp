#pragma once
// Overtaking on two-lane roads with oncoming traffic: the decision model of VTISim (Brodin &
// Carlsson 1986) as the thesis describes it (ch. 2.3.3, papers I and II). A driver held up by a
// slower leader asks four questions (thesis section 2.3.3):
//
//   1. restrictions: is the stretch the overtaking needs free of overtaking restrictions?
//   2. gap:          is the available gap (to the oncoming vehicle, or to the end of the sight
//                    distance) longer than the overtaking needs, with a safety margin?
//   3. capability:   can the vehicle pass at all (a passing speed clearly above the leader's,
//                    reached within a reasonable distance)?
//   4. willingness:  does the driver accept this gap? A probability of acceptance as a function
//                    of the available gap, different for flying overtakings (the overtaker is still
//                    closing in on the leader) and accelerated ones (it follows the leader and
//                    must accelerate first). Every decision is a new draw: an inconsistent driver
//                    model, which the thesis cites as closer to observed behaviour than a fixed
//                    critical gap per driver (McLean 1989).
//
// The pass itself is planned with constant acceleration up to a passing speed that may exceed the
// driver's desired speed (paper I/II: overtaking drivers do not keep to their desired speed or to
// the limit), and reviewed at every step: when the oncoming vehicle leaves too little time to
// finish, the driver aborts (brakes and returns behind the overtaken vehicle) unless it is
// already so far past it that finishing is the safer choice.
//
// Pure functions of the parameters and the situation; the caller owns the state machine
// (traffic/overtaking_manoeuvre.hpp) and the random draw.

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace entourage {

// Probability of accepting an available gap: piecewise linear through `points` (gap_m,
// probability), sorted by gap, constant beyond both ends (the first point's probability below
// it, the last point's above it). An empty curve accepts nothing.
struct AcceptanceCurve {
  std::vector<std::pair<double, double>> points;

  double probability(double gap_m) const;
};

struct OvertakingParams {
  // Illustrative shapes after the thesis's Figure 2.10 (Carlsson 1993: with an oncoming vehicle in
  // sight, a flying overtaking is accepted more readily than an accelerated one at the same gap).
  AcceptanceCurve flying{{{200.0, 0.0}, {400.0, 0.3}, {600.0, 0.7}, {800.0, 0.9}, {1000.0, 1.0}}};
  AcceptanceCurve accelerated{{{300.0, 0.0}, {500.0, 0.2}, {700.0, 0.5}, {900.0, 0.8}, {1100.0, 0.95}}};
  // A flying overtaking: the overtaker still closes in on the leader at least this fast.
  double flying_min_closing_mps = 1.5;
  // A driver only considers overtaking a leader this close (bumper to bumper).
  double consider_gap_m = 80.0;
  // Accelerated overtakings are reconsidered this often while following (a new draw each time).
  double decision_interval_s = 1.0;
  // The passing speed: up to this times the driver's desired speed (paper I/II).
  double speed_excess_ratio = 1.15;
  // Capability: the passing speed must beat the leader's by at least this.
  double min_speed_gain_mps = 3.0;
  // Share of the driver's maximum acceleration used while passing.
  double accel_share = 1.0;
  // Capability (question 3): no overtaking that needs more road than this (thesis: "more than one
  // kilometre").
  double max_distance_m = 1000.0;
  // Lateral movement into the oncoming lane and back.
  double lateral_s = 2.5;
  // Back in the own lane this time gap (at the overtaken vehicle's speed) ahead of it, plus the
  // overtaker's min_gap_m.
  double return_time_gap_s = 0.6;
  // The oncoming vehicle must still be this far away in time when the overtaker is back.
  double safety_margin_s = 3.0;
  // Speed assumed for an oncoming vehicle hidden beyond the sight distance.
  double hidden_oncoming_speed_mps = 25.0;
  // During the pass: abort when finishing would leave less than this margin.
  double abort_margin_s = 1.0;
  // A pass in which the overtaker's rear is already ahead of the overtaken vehicle's front minus
  // this share of the overtaken vehicle's length is finished rather than aborted.
  double commit_share = 0.5;
  // Moving back into the own lane (after a pass, or aborting one) the overtaker accepts any gap in
  // which neither it, behind its new leader, nor its new follower, behind it, has to brake harder
  // than this to keep its standstill gap (kinematics at constant speeds: closing^2 / (2 (gap -
  // s0))). Drivers cut back in at short time gaps when the oncoming lane is needed; the full
  // return_time_gap_s is what they aim for, not what they insist on.
  double return_decel_mps2 = 3.0;
  // With an oncoming vehicle about to meet it, the overtaker accepts a gap up to its own braking
  // limit; its new follower, whose brakes it cannot know, is asked at most this: the weakest
  // braking limit among the scenario's vehicle types (set from them, not a scenario field).
  double follower_max_decel_mps2 = std::numeric_limits<double>::infinity();
};

enum class OvertakingKind : std::uint8_t { kFlying = 0, kAccelerated = 1 };

// What the overtaker knows when it decides (its own lane leader is the vehicle to overtake).
struct OvertakingSituation {
  double speed_mps = 0.0;          // the overtaker's speed
  double desired_speed_mps = 0.0;  // its desired speed on this section
  double max_accel_mps2 = 1.0;     // its acceleration capability
  double length_m = 4.5;
  double min_gap_m = 2.0;           // its standstill gap (s0), kept at the return
  double leader_gap_m = 0.0;       // bumper to bumper, to the vehicle to overtake
  double leader_speed_mps = 0.0;
  double leader_length_m = 4.5;
  // Room in front of the overtaken vehicle (to its own leader's rear); infinite if none.
  double room_ahead_of_leader_m = std::numeric_limits<double>::infinity();
  // From the overtaker's front to the nearest oncoming vehicle's front in the oncoming lane.
  double oncoming_distance_m = std::numeric_limits<double>::infinity();
  double oncoming_speed_mps = 0.0;
  double sight_distance_m = std::numeric_limits<double>::infinity();  // of the oncoming lane
  double restriction_free_m = std::numeric_limits<double>::infinity();  // ahead, free of restrictions
};

// The pass as planned from the current situation.
struct PassPlan {
  bool feasible = false;
  double passing_speed_mps = 0.0;  // the top speed of the pass
  double duration_s = 0.0;         // until the overtaker is back in its lane (lateral moves included)
  double distance_m = 0.0;         // road the overtaker covers in that time
  double relative_distance_m = 0.0;  // how far it must gain on the overtaken vehicle
};

// Kinematics of a pass: from `speed_mps`, accelerate at accel_share * max_accel up to the passing
// speed (speed_excess_ratio * desired, never below the current speed), gaining
// `relative_distance_m` on a leader at constant speed, then the lateral move back. Infeasible when
// the passing speed does not beat the leader's by min_speed_gain_mps.
PassPlan plan_pass(const OvertakingParams& p, const OvertakingSituation& s);

// The relative distance a pass must gain from the situation: behind the leader by leader_gap_m,
// past it by both lengths and the return gap.
double relative_distance_to_pass_m(const OvertakingParams& p, const OvertakingSituation& s);

// The gap the plan needs: its distance plus what the oncoming vehicle covers meanwhile and in
// the safety margin.
double required_gap_m(const OvertakingParams& p, const PassPlan& plan, double oncoming_speed_mps);

enum class OvertakingVerdict : std::uint8_t {
  kAccepted = 0,
  kNoLeader = 1,      // no one to overtake close enough, or the leader is not slower
  kRestricted = 2,    // question 1
  kGapTooShort = 3,   // question 2
  kNotCapable = 4,    // question 3
  kUnwilling = 5,     // question 4
};

struct OvertakingDecision {
  OvertakingVerdict verdict = OvertakingVerdict::kNoLeader;
  OvertakingKind kind = OvertakingKind::kAccelerated;
  PassPlan plan;
  double available_gap_m = 0.0;  // min(oncoming distance, sight distance)
  double acceptance_probability = 0.0;

  bool accepted() const { return verdict == OvertakingVerdict::kAccepted; }
};

OvertakingKind classify(const OvertakingParams& p, const OvertakingSituation& s);

// The four questions in order; `uniform_draw` in [0, 1) is the driver's draw for willingness
// (accepted when draw < probability).
OvertakingDecision decide_overtaking(const OvertakingParams& p, const OvertakingSituation& s, double uniform_draw);

// During the pass (the overtaker in the oncoming lane, the overtaken vehicle its "leader" in its
// own lane, now possibly beside or behind it: leader_gap_m is then negative, down to
// -(leader_length + length) when the overtaker's rear is at the overtaken vehicle's front).
enum class PassAction : std::uint8_t {
  kContinue = 0,  // keep passing
  kReturn = 1,    // far enough ahead of the overtaken vehicle, and room there: move back
  kAbort = 2,     // cannot finish in time: brake and return behind the overtaken vehicle
};

struct PassReview {
  PassAction action = PassAction::kContinue;
  PassPlan remaining;  // the rest of the pass as planned now
  // The rest can be finished with abort_margin_s to spare before the oncoming vehicle.
  bool safe_to_finish = false;
};

PassReview review_pass(const OvertakingParams& p, const OvertakingSituation& s);

}  // namespace entourage
