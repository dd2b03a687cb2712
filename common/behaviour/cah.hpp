#pragma once
// The constant-acceleration heuristic (CAH) and the ACC model's blend of it with IDM (Kesting,
// Treiber & Helbing 2010, "Enhanced intelligent driver model to access the impact of driving
// strategies on traffic capacity", Phil. Trans. R. Soc. A 368, 4585-4605).
//
// IDM brakes far harder than needed when a leader appears at a gap well below the desired one but
// is not closing in fast: a vehicle changing into the lane ahead (IDM's s*/s term grows with the
// approach rate at any gap). CAH is the acceleration that avoids a collision if both keep their
// accelerations, the leader's taken as a~ = min(a_l, a):
//
//   a_CAH = v^2 a~ / (v_l^2 - 2 s a~)              if v_l (v - v_l) <= -2 s a~
//         = a~ - (v - v_l)^2 H(v - v_l) / (2 s)     otherwise            (H: step function)
//
// and the ACC model keeps IDM where it is the milder of the two, else blends towards CAH:
//
//   a_ACC = a_IDM                                                     if a_IDM >= a_CAH
//         = (1 - c) a_IDM + c [a_CAH + b tanh((a_IDM - a_CAH) / b)]    otherwise
//
// with the coolness c (0: IDM; the paper's 0.99) and the driver's comfortable deceleration b. In
// equilibrium (dv = 0, a_l = 0) a_CAH = 0 = a_IDM, so the model's fundamental diagram is IDM's.

namespace entourage {

// a_CAH for a driver of maximum acceleration `max_accel_mps2` at `speed_mps`, behind a leader at
// `gap_m` (> 0) driving at `leader_speed_mps` with `leader_accel_mps2`.
double cah_accel_mps2(double max_accel_mps2, double speed_mps, double gap_m, double leader_speed_mps,
                      double leader_accel_mps2);

// The ACC model's blend of an IDM-family acceleration `idm_mps2` with `cah_mps2`.
double acc_blend_mps2(double idm_mps2, double cah_mps2, double coolness, double comfort_decel_mps2);

}  // namespace entourage
