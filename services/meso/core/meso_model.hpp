#pragma once
// The mesoscopic vehicle update of the outer regions. A vehicle's speed follows from the gap to
// its leader through its own car-following model's equilibrium speed-gap relation (equilibrium.hpp:
// the model's fundamental diagram, i.e. a speed-density relation per lane), so meso vehicles settle
// at the speeds micro vehicles would have at the same gaps:
//
//   v_eq     = V_e(gap)                              (the desired speed v0 on a free road)
//   v_eq     = min(v_eq, v0_local)                   (speed adaptation: limits, curves ahead)
//   v_brake  = v_leader + sqrt(2 b (gap - s0))       (can still brake comfortably to the leader)
//   v_next   = clamp(min(v_eq, v_brake), v - b_max dt, v + a dt), at least 0
//   v_next   = min(v_next, (gap - s_floor) / dt)     never into the leader (emergency)
//   s_next   = s + v_next dt                         (along the direction of travel)
//
// with the driver's a, b, s0 and the vehicle's braking limit b_max. The order within a lane is
// kept: a vehicle never reaches its leader, which only moves forward. Lane choice: meso_lanes.hpp.

#include <algorithm>
#include <cmath>

#include "meso/core/equilibrium.hpp"
#include "traffic/vehicle.hpp"

namespace entourage::meso {

// Closest a meso vehicle comes to its leader, bumper to bumper.
inline constexpr double kFloorGap_m = 0.5;

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
                            double dt_s) {
  const IdmParams& p = v.driver.car_following.idm;
  double target = desired_speed_mps;
  if (ahead.gap_m >= 0.0) {
    const double room = std::max(0.0, ahead.gap_m - p.min_gap_m);
    target = std::min({target, eq.at(ahead.gap_m),
                       ahead.leader_speed_mps + std::sqrt(2.0 * p.comfort_decel_mps2 * room)});
  }
  const double lo = std::max(0.0, v.speed_mps - v.driver.max_decel_mps2 * dt_s);
  const double hi = v.speed_mps + p.max_accel_mps2 * dt_s;
  MesoSpeed out{std::clamp(target, lo, hi), false};
  if (ahead.gap_m >= 0.0) {
    const double guard = std::max(0.0, (ahead.gap_m - kFloorGap_m) / dt_s);
    if (guard < out.speed_mps) out = {guard, true};
  }
  return out;
}

}  // namespace entourage::meso
