#pragma once
// The mesoscopic vehicle update of the outer regions. A vehicle's speed relaxes towards the speed
// its own car-following model has in equilibrium at its gap (equilibrium.hpp: the model's
// fundamental diagram, a speed-density relation per lane), so meso vehicles settle at the speeds
// micro vehicles would have at the same gaps; a kinematic bound keeps it safe. A vehicle is
// planned once per update period T = k dt (k steps, `update_period_s`), not at every step: the
// plan is the speed v_next it reaches after T, on a straight ramp (constant acceleration) that the
// core integrates step by step until the next plan:
//
//   v_eq    = min(V_e(gap + T (v_leader - v)), v0_local)   (the gap expected after T, the present
//                                                     one when T is one step; v0_local: speed
//                                                     adaptation, limits ahead)
//   v_relax = v + clamp((v_eq - v) (1 - exp(-T / tau)), -b T, a T)
//   v_model = v + max(a_cf, -b_max) T   if a_cf < -b, else unbounded   (a_cf: the driver's own
//                                                     car-following model's acceleration now
//                                                     behind a vehicle of its direction: closing
//                                                     in too fast, it brakes as micro would)
//   v_safe  = v_leader + sqrt(2 b (gap - s0))         (can still brake comfortably to the leader)
//   v_next  = min(v_relax, v_model)      if that is <= v_safe
//           = max(v_safe, v - b_max T)   otherwise (brakes harder, up to the vehicle's limit)
//   a       = min((v_next - v) / T, a_guard)         a_guard: the highest rate whose steps stay
//                                                     s_floor behind the leader at every step of
//                                                     the period, the leader braking at the
//                                                     friction limit: never into it (emergency)
//   each step: v = max(0, v + a dt),  s += v dt       (along the direction of travel)
//
// with the driver's a, b, s0, the vehicle's braking limit b_max and the relaxation time tau. A
// vehicle off its equilibrium (after a handoff, behind a vehicle that just entered or
// changed lanes) returns to it at comfortable rates instead of jumping to V_e(gap); only a leader
// too close to brake for comfortably makes it brake harder. The order within a lane is kept: a
// vehicle never reaches its leader. Lane choice: meso_lanes.hpp.

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "behaviour/car_following.hpp"
#include "meso/core/equilibrium.hpp"
#include "traffic/vehicle.hpp"

namespace entourage::meso {

struct MesoModelParams {
  double relaxation_time_s = 1.0;  // tau: how fast speed returns to equilibrium (bounded by a and b)
  double floor_gap_m = 0.5;        // closest a meso vehicle comes to its leader, bumper to bumper
  double leader_brake_limit_mps2 = 10.0;  // the hardest any leader can brake (about 1 g)
  // T: how often a vehicle is planned (rounded to whole steps). Once per second, a driver's
  // reaction time, is what makes meso cheap: services/meso/README.md, *Cost*.
  double update_period_s = 1.0;
};

// How far a plan reaches: `steps` steps of `dt_s` each.
struct PlanHorizon {
  double dt_s = 0.1;
  int steps = 1;
  double length_s() const { return dt_s * steps; }
};

// What a vehicle has ahead of it: a vehicle of its direction in its lane (its leader), a vehicle
// of the other direction in its lane (an overtaker that has not returned yet), or the end of its
// lane (a closure).
enum class Obstacle : std::uint8_t { kLeader, kOncoming, kLaneEnd };

struct Ahead {
  double gap_m = -1.0;  // < 0: no leader
  double leader_speed_mps = 0.0;
  double leader_accel_mps2 = 0.0;
  Obstacle obstacle = Obstacle::kLeader;
};

struct MesoSpeed {
  double speed_mps = 0.0;   // at the end of the horizon
  double accel_mps2 = 0.0;  // the ramp's constant rate (the speed stays at 0 once it gets there)
  bool emergency = false;   // the floor-gap guard overrode the braking limit
};

// The highest constant acceleration from `speed_mps` whose steps keep `floor_m` behind a leader
// `gap_m` ahead at `leader_speed_mps` that brakes at `leader_brake_mps2` from the first step, at
// every step of the horizon (each step moves a vehicle at its speed after that step's change;
// a speed that would fall below 0 stays at 0, which only travels less).
inline double guard_accel_mps2(double speed_mps, double gap_m, double leader_speed_mps, double leader_brake_mps2,
                               double floor_m, const PlanHorizon& h) {
  double bound = std::numeric_limits<double>::infinity();
  double leader_mps = leader_speed_mps;
  double leader_travel_m = 0.0;
  for (int i = 1; i <= h.steps; ++i) {
    leader_mps = std::max(0.0, leader_mps - leader_brake_mps2 * h.dt_s);
    leader_travel_m += leader_mps * h.dt_s;
    // steps 1..i travel i dt v + a dt^2 i (i + 1) / 2
    const double room_m = gap_m - floor_m + leader_travel_m - i * h.dt_s * speed_mps;
    bound = std::min(bound, room_m / (h.dt_s * h.dt_s * i * (i + 1) / 2.0));
  }
  return bound;
}

// A cheap test that guard_accel_mps2 is at least `accel_mps2`, so that most plans (a leader far
// enough ahead) skip its loop: the room at step i is at least the gap less the floor and the
// distance covered at the present speed over the whole horizon (the leader's own travel is never
// negative), and a positive rate needs at most its value times dt^2 n (n + 1) / 2 by the last step.
// (A small margin keeps rounding in the loop from deciding otherwise.)
inline bool guard_cannot_bind(double accel_mps2, double speed_mps, double gap_m, double floor_m, const PlanHorizon& h) {
  constexpr double kRoundingMargin_m = 1e-6;
  const double n = h.steps;
  const double least_room_m = gap_m - floor_m - n * h.dt_s * speed_mps;
  return least_room_m >= std::max(0.0, accel_mps2) * h.dt_s * h.dt_s * n * (n + 1) / 2.0 + kRoundingMargin_m;
}

// `desired_speed_mps`: the driver's desired speed at its place (speed adaptation, look-ahead).
// `eq`: the equilibrium of the car-following model it drives by (its driver's own, or with the
// desired speed the director raised it to); that model also judges closing in.
inline MesoSpeed next_speed(const Vehicle& v, const EquilibriumSpeed& eq, const Ahead& ahead, double desired_speed_mps,
                            const PlanHorizon& h, const MesoModelParams& m = {}) {
  const IdmParams& p = v.driver.car_following.idm;
  const double t = h.length_s();
  const bool led = ahead.gap_m >= 0.0;
  // The equilibrium at the gap expected at the end of the period: without that anticipation a
  // platoon planned once a second oscillates (each driver answers the gap its leader left a
  // period ago). Planned at every step, at the present gap, as before plans had periods.
  const double expected_gap_m =
      h.steps > 1 ? std::max(0.0, ahead.gap_m + t * (ahead.leader_speed_mps - v.speed_mps)) : ahead.gap_m;
  const double target = led ? std::min(desired_speed_mps, eq.at(expected_gap_m)) : desired_speed_mps;
  // The relaxation dv/dt = (v_eq - v) / tau solved over the period (not a step of length T on its
  // slope, which reached the target in one period: the outer traffic then settled twice as fast
  // as with per-step plans, and the cut-in play succeeded in 64 % of 50 runs instead of 74 %).
  const double relaxed = 1.0 - std::exp(-t / m.relaxation_time_s);
  const double change = std::clamp((target - v.speed_mps) * relaxed, -p.comfort_decel_mps2 * t, p.max_accel_mps2 * t);
  double next = v.speed_mps + change;
  if (led) {
    // Closing in faster than its own model would brake for comfortably: it brakes as that model
    // does (a meso vehicle at 35 m/s 70 m behind a micro one at 26 m/s kept its speed, its
    // equilibrium at that gap being above it, and micro's model braked at 9 m/s^2 at the border).
    // (Not for an oncoming overtaker, expected back in its lane, nor a lane's end, left by a lane
    // change: those are braked for only when comfortable braking no longer suffices.)
    const LeaderView leader{ahead.gap_m, ahead.leader_speed_mps, ahead.leader_accel_mps2};
    const double model_accel = ahead.obstacle == Obstacle::kLeader
                                   ? car_following_accel_mps2(eq.params(), v.speed_mps, &leader)
                                   : 0.0;
    if (model_accel < -p.comfort_decel_mps2) {
      next = std::min(next, v.speed_mps + std::max(model_accel, -v.driver.max_decel_mps2) * t);
    }
    const double room = std::max(0.0, ahead.gap_m - p.min_gap_m);
    const double safe = ahead.leader_speed_mps + std::sqrt(2.0 * p.comfort_decel_mps2 * room);
    if (next > safe) next = std::max(safe, v.speed_mps - v.driver.max_decel_mps2 * t);
  }
  next = std::max(0.0, next);
  const MesoSpeed out{next, (next - v.speed_mps) / t, false};
  if (!led || guard_cannot_bind(out.accel_mps2, v.speed_mps, ahead.gap_m, m.floor_gap_m, h)) return out;
  const double guard = guard_accel_mps2(v.speed_mps, ahead.gap_m, ahead.leader_speed_mps, m.leader_brake_limit_mps2,
                                        m.floor_gap_m, h);
  if (guard >= out.accel_mps2) return out;
  return {std::max(0.0, v.speed_mps + guard * t), guard, true};
}

}  // namespace entourage::meso
