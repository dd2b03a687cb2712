#pragma once
// The modified IDM (after Olstam & Tapani, paper V of the thesis): the IDM's interaction term
// makes a driver react to a leader far beyond any safety distance (at a gap of 3 s*, IDM still
// brakes by a/9), so drivers never reach their desired speed in moderate traffic and move away
// from lane changes they should not care about. The modified model ignores a leader further than
// beta times the desired gap s*:
//
//   a = a [1 - (v/v0)^delta] + w(s / s*) a_int,      a_int = -a (s*/s)^2 (IDM's term)
//   w(r) = 1                                  for r <= 1        (identical to IDM when closer than s*)
//   w(r) = 1 - S((r - 1) / (beta - 1))        for 1 < r < beta  (S: smoothstep 3x^2 - 2x^3)
//   w(r) = 0                                  for r >= beta     (no interaction at all)
//
// The weight is continuous with a continuous derivative, so the acceleration is continuous in the
// gap. This is the formula Entourage uses; paper V states the properties (zero interaction beyond
// beta s*, IDM for close leaders, continuity) and beta = 1.35, which this form has exactly while
// keeping IDM unchanged wherever the gap is below s*, i.e. in every critical situation.

#include "behaviour/idm.hpp"

namespace entourage {

// The weight w(s / s*) of IDM's interaction term.
double modified_idm_weight(double gap_m, double desired_gap_m, double beta);

// Acceleration of the modified IDM behind a leader.
double modified_idm_accel_mps2(const IdmParams& p, double beta, double speed_mps, double gap_m,
                               double leader_speed_mps);

}  // namespace entourage
