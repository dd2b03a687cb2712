#pragma once
// The mesoscopic vehicle update of the outer regions. A vehicle's speed relaxes towards the speed
// its own car-following model has in equilibrium at its gap (equilibrium.hpp: the model's
// fundamental diagram, a speed-density relation per lane), so meso vehicles settle at the speeds
// micro vehicles would have at the same gaps; a kinematic bound keeps it safe:
//
//   v_eq    = min(V_e(gap), v0_local)                 (v0_local: speed adaptation, limits ahead)
//   v_relax = v + clamp((v_eq - v) dt / tau, -b dt, a dt)
//   v_safe  = v_leader + sqrt(2 b (gap - s0))         (can still brake comfortably to the leader)
//   v_next  = v_relax                    if v_relax <= v_safe
//           = max(v_safe, v - b_max dt)  otherwise (brakes harder, up to the vehicle's limit)
//   v_next  = min(v_next, (gap - s_floor) / dt + v_leader_low)   never into the leader (emergency)
//   s_next  = s + v_next dt                           (along the direction of travel)
//
// with the driver's a, b, s0, the vehicle's braking limit b_max, the relaxation time tau, and
// v_leader_low the slowest the leader can drive in this step (braking at the friction limit).
// A vehicle off its equilibrium (after a handoff, behind a vehicle that just entered or changed
// lanes) returns to it at comfortable rates instead of jumping to V_e(gap); only a leader too
// close to brake for comfortably makes it brake harder. The order within a lane is kept: a
// vehicle never reaches its leader. Lane choice: meso_lanes.hpp.

#include <algorithm>
#include <cmath>

#include "meso/core/equilibrium.hpp"
#include "traffic/vehicle.hpp"

namespace entourage::meso {

struct MesoModelParams {
  double relaxation_time_s = 1.0;  // tau: how fast speed returns to equilibrium (bounded by a and b)
  double floor_gap_m = 0.5;        // closest a meso vehicle comes to its leader, bumper to bumper
  double leader_brake_limit_mps2 = 10.0;  // the hardest any leader can brake (about 1 g)
};

struct Ahead {
  double gap_m = -1.0;  // < 0: no leader
  double leader_speed_mps = 0.0;
};

struct MesoSpeed {
  double speed_mps = 0.0;
  bool emergency = false;  // the floor-gap guard overrode the braking limit
};

// `desired_speed_mps`: the driver's desired speed at its place (speed adaptation, look-ahead).
inline MesoSpeed next_speed(const Vehicle& v, const EquilibriumSpeed& eq, const Ahead& ahead, double desired_speed_mps,
                            double dt_s, const MesoModelParams& m = {}) {
  const IdmParams& p = v.driver.car_following.idm;
  const bool led = ahead.gap_m >= 0.0;
  const double target = led ? std::min(desired_speed_mps, eq.at(ahead.gap_m)) : desired_speed_mps;
  const double change = std::clamp((target - v.speed_mps) * dt_s / m.relaxation_time_s,
                                   -p.comfort_decel_mps2 * dt_s, p.max_accel_mps2 * dt_s);
  double next = v.speed_mps + change;
  if (led) {
    const double room = std::max(0.0, ahead.gap_m - p.min_gap_m);
    const double safe = ahead.leader_speed_mps + std::sqrt(2.0 * p.comfort_decel_mps2 * room);
    if (next > safe) next = std::max(safe, v.speed_mps - v.driver.max_decel_mps2 * dt_s);
  }
  MesoSpeed out{std::max(0.0, next), false};
  if (led) {
    const double leader_low = std::max(0.0, ahead.leader_speed_mps - m.leader_brake_limit_mps2 * dt_s);
    const double guard = std::max(0.0, (ahead.gap_m - m.floor_gap_m) / dt_s + leader_low);
    if (guard < out.speed_mps) out = {guard, true};
  }
  return out;
}

}  // namespace entourage::meso
