#pragma once
// Intelligent Driver Model (Treiber, Hennecke & Helbing 2000, Phys. Rev. E 62, 1805):
//
//   a_IDM(v, s, dv) = a [ 1 - (v / v0)^delta - (s*(v, dv) / s)^2 ],
//   s*(v, dv)       = s0 + max(0, v T + v dv / (2 sqrt(a b))),
//
// with gap s (bumper to bumper), approach rate dv = v - v_leader. Its equilibrium gap at speed v
// (dv = 0, a = 0) is s_e(v) = s*(v, 0) / sqrt(1 - (v / v0)^delta).

namespace entourage {

struct IdmParams {
  double desired_speed_mps = 33.3;  // v0
  double time_gap_s = 1.5;          // T
  double max_accel_mps2 = 1.0;      // a
  double comfort_decel_mps2 = 1.5;  // b
  double min_gap_m = 2.0;           // s0
  double accel_exponent = 4.0;      // delta
};

// (v / v0)^delta, with the common delta = 4 computed without pow().
double idm_speed_ratio_term(const IdmParams& p, double speed_mps);

// Desired dynamic gap s*(v, dv).
double idm_desired_gap_m(const IdmParams& p, double speed_mps, double approach_rate_mps);

// Free-road acceleration a [1 - (v/v0)^delta].
double idm_free_accel_mps2(const IdmParams& p, double speed_mps);

// Interaction term -a (s*/s)^2 (0 for an infinite gap).
double idm_interaction_mps2(const IdmParams& p, double speed_mps, double gap_m, double leader_speed_mps);

// Full IDM acceleration behind a leader at `gap_m` driving at `leader_speed_mps`.
double idm_accel_mps2(const IdmParams& p, double speed_mps, double gap_m, double leader_speed_mps);

// Equilibrium gap s_e(v); infinite for v >= v0.
double idm_equilibrium_gap_m(const IdmParams& p, double speed_mps);

}  // namespace entourage
