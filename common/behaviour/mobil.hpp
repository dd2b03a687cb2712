#pragma once
// MOBIL, "Minimizing Overall Braking Induced by Lane changes" (Kesting, Treiber & Helbing 2007,
// Transp. Res. Rec. 1999, 86-94). A driver c considers a change to an adjacent lane; n is the
// new follower in the target lane, o the old follower in the present lane; a is an acceleration
// before the change and a~ after it, all from the car-following model.
//
//   safety:    a~_n >= -b_safe            (and a~_c >= -b_safe: the changer itself)
//   incentive: a~_c - a_c + p [(a~_n - a_n) + (a~_o - a_o)] > delta_a_th + bias,
//
// with bias = +a_bias for a change to the left and -a_bias for a change to the right (a
// preference for the right lane, Kesting et al.'s asymmetric "keep right" variant).

namespace entourage {

struct MobilParams {
  double politeness = 0.2;             // p
  double change_threshold_mps2 = 0.1;  // delta a_th
  double right_bias_mps2 = 0.3;        // a_bias
  double safe_decel_mps2 = 4.0;        // b_safe
};

// The accelerations MOBIL compares. Followers that do not exist contribute 0 before and after.
struct MobilSituation {
  bool to_right = false;
  double self_now_mps2 = 0.0;
  double self_after_mps2 = 0.0;
  double new_follower_now_mps2 = 0.0;
  double new_follower_after_mps2 = 0.0;
  double old_follower_now_mps2 = 0.0;
  double old_follower_after_mps2 = 0.0;
};

struct MobilDecision {
  bool safe = false;
  double advantage_mps2 = 0.0;  // incentive minus threshold and bias; > 0 means change
  bool change = false;
};

MobilDecision mobil_decide(const MobilParams& p, const MobilSituation& s);

// MOBIL's safety criterion alone: neither the changing driver nor its new follower would have to
// brake harder than the safe deceleration. A caller may test it first and skip the incentive
// (whose accelerations cost more to compute) when it fails.
bool mobil_safe(const MobilParams& p, double self_after_mps2, double new_follower_after_mps2);

}  // namespace entourage
