#pragma once
// Gipps' car-following model (Gipps 1981, "A behavioural car-following model for computer
// simulation", Transp. Res. B 15, 105-111). Over a reaction time tau a driver chooses the lower of
//
//   v_a = v + 2.5 a tau (1 - v / v0) sqrt(0.025 + v / v0)                       (free)
//   v_b = -b tau + sqrt(b^2 tau^2 + b [2 (dx - S) - v tau + v_l^2 / b_hat])      (safe)
//
// with dx the distance between the fronts of leader and follower (gap + leader length), S the
// leader's effective size (length + the minimum gap s0), b the driver's most severe braking and
// b_hat its estimate of the leader's (both positive here; Gipps writes them negative, which flips
// the signs inside the root), v_l the leader's speed. v_b is the highest speed from which the
// driver, reacting tau/2 late, still stops behind a leader that brakes at b_hat. Since
// dx - S = gap - s0, the leader's length cancels. v0, a and s0 are the IDM parameters of the
// driver (desired speed, maximum acceleration, minimum gap).
//
// Entourage runs every model at the scenario's step dt, so Gipps' speed update over tau is turned
// into an acceleration: a = (min(v_a, v_b) - v) / tau. For the free term this is exactly
// 2.5 a (1 - v/v0) sqrt(0.025 + v/v0), independent of tau; behind a leader the driver closes the
// difference to the safe speed at the rate Gipps' update implies. The emergency regime
// (traffic/driving.hpp) remains the safety net, as for every model.

#include "behaviour/idm.hpp"
#include "behaviour/leader_view.hpp"

namespace entourage {

struct GippsParams {
  double reaction_time_s = 0.66;          // tau (Gipps: 2/3 s)
  double max_decel_mps2 = 3.0;            // b: the most severe braking the driver wishes to use
  double leader_decel_estimate_mps2 = 3.0;  // b_hat
};

// Speed after tau on a free road, and behind a leader at gap_m (bumper to bumper).
double gipps_free_speed_mps(const IdmParams& idm, const GippsParams& p, double speed_mps);
double gipps_safe_speed_mps(const IdmParams& idm, const GippsParams& p, double speed_mps, double gap_m,
                            double leader_speed_mps);

// Acceleration (v_next - v) / tau, v_next = min(free, safe).
double gipps_accel_mps2(const IdmParams& idm, const GippsParams& p, double speed_mps, const LeaderView* leader);

}  // namespace entourage
