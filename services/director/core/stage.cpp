#include "director/core/stage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace entourage::director {

namespace {
bool fits(const PlayConfig& play, int ego_lane, int side, const Lanes& lanes) {
  auto ok = [&](int offset) {
    const int lane = ego_lane + side * offset;
    return lane >= 0 && lane < lanes.forward;
  };
  for (const PlayRoleConfig& r : play.roles) {
    if (r.direction == Direction::kForward && !ok(r.lane_offset)) return false;
  }
  for (const PlayClearZoneConfig& z : play.clear) {
    if (!ok(z.lane_offset)) return false;
  }
  return true;
}
}  // namespace

int staging_lane(const EgoObservation& ego, const Lanes& lanes) {
  return std::clamp(ego.target_lane, 0, std::max(0, lanes.of(ego.direction) - 1));
}

bool mirrored_beside(const PlayConfig& play, int ego_lane, const Lanes& lanes) {
  return !fits(play, ego_lane, 1, lanes) && fits(play, ego_lane, -1, lanes);
}

PlayConfig staged_beside(const PlayConfig& play, int ego_lane, const Lanes& lanes) {
  if (!mirrored_beside(play, ego_lane, lanes)) return play;
  PlayConfig m = play;
  for (PlayRoleConfig& r : m.roles) {
    if (r.direction == Direction::kForward) r.lane_offset = -r.lane_offset;
  }
  for (PlayClearZoneConfig& z : m.clear) z.lane_offset = -z.lane_offset;
  constexpr std::uint8_t kLeft = 1;
  constexpr std::uint8_t kRight = 2;
  for (PlayActionConfig& a : m.actions) {
    if (m.roles[static_cast<std::size_t>(a.role)].direction != Direction::kForward) continue;
    if (a.kind == PlayActionKind::kLaneChange) a.lane_offset = -a.lane_offset;
    if (a.kind == PlayActionKind::kIndicator && (a.indicator == kLeft || a.indicator == kRight)) {
      a.indicator = a.indicator == kLeft ? kRight : kLeft;
    }
  }
  return m;
}

Aim aim_of(double time_to_start_s, double trigger2_s_m, double speed_at_start_mps, const EgoObservation& ego,
           double horizon_s) {
  if (time_to_start_s >= horizon_s) return {time_to_start_s, trigger2_s_m, speed_at_start_mps, 0.0};
  const double v = std::max(ego.speed_mps, 0.0);
  return {horizon_s, ego.s_m + sign(ego.direction) * v * horizon_s, v, horizon_s - std::max(time_to_start_s, 0.0)};
}

double start_speed_mps(const PlayRoleConfig& role, double ego_speed_mps) {
  return play_speed_mps(role.absolute_speed, role.speed_mps, ego_speed_mps);
}

namespace {
Direction role_direction(const PlayRoleConfig& role, Direction ego_direction) {
  return role.direction == Direction::kForward ? ego_direction : opposite(ego_direction);
}

// A role's speed along the ego's direction less the ego's (an oncoming role's start speed takes it
// the other way).
double relative_speed_mps(Direction direction, Direction ego_direction, double speed_mps, double ego_speed_mps) {
  return sign(direction) * sign(ego_direction) * speed_mps - ego_speed_mps;
}

// +1 for a role ahead of the ego at the start (or beside it), -1 for one behind.
double ahead_sign(const PlayRoleConfig& role) { return role.ahead_m >= 0.0 ? 1.0 : -1.0; }

// How fast the ego closes on a role at `relative_mps` (m/s; 0 where it does not): a slower role
// ahead of the ego, an oncoming one, a faster one behind it.
double closing_speed_mps(const PlayRoleConfig& role, double relative_mps) {
  return std::max(0.0, -relative_mps * ahead_sign(role));
}
}  // namespace

double late_aim_s(const PlayConfig& play, Direction ego_direction, double ego_speed_mps) {
  double late_s = std::numeric_limits<double>::infinity();
  for (const PlayRoleConfig& r : play.roles) {
    const double closing_mps = closing_speed_mps(
        r, relative_speed_mps(role_direction(r, ego_direction), ego_direction, start_speed_mps(r, ego_speed_mps),
                              ego_speed_mps));
    if (closing_mps > 0.0) late_s = std::min(late_s, kLateShare * r.position_tolerance_m / closing_mps);
  }
  return std::isfinite(late_s) ? late_s : 0.0;
}

std::vector<Slot> slots_of(const PlayConfig& play, Direction ego_direction, int ego_lane, const Aim& aim,
                           const Lanes& lanes) {
  std::vector<Slot> out;
  out.reserve(play.roles.size());
  const double late_s = late_aim_s(play, ego_direction, aim.ego_speed_mps);
  for (const PlayRoleConfig& r : play.roles) {
    Slot s;
    s.direction = role_direction(r, ego_direction);
    const int lane = r.direction == Direction::kForward ? ego_lane + r.lane_offset : r.lane_offset;
    s.lane = std::clamp(lane, 0, std::max(0, lanes.of(s.direction) - 1));
    s.speed_mps = start_speed_mps(r, aim.ego_speed_mps);
    const double relative_mps = relative_speed_mps(s.direction, ego_direction, s.speed_mps, aim.ego_speed_mps);
    const double late_m = ahead_sign(r) * late_s * closing_speed_mps(r, relative_mps);  // further from the ego
    s.s_m = aim.ego_s_m + sign(ego_direction) * (r.ahead_m + late_m + relative_mps * aim.past_start_s);
    out.push_back(s);
  }
  return out;
}

namespace {
// How long before the start a role settles on its start's track (way_to; 0: it does not): an
// oncoming role kOncomingSettle_s; one of the ego's direction, ahead of the ego, the ego closing on
// it by more than kSettleClosing_mps, with a lane of its direction beside it for the traffic
// behind it to pass in, kSettleEarly_s.
double settling_s(const Slot& slot, const PlayRoleConfig& role, Direction ego_direction, double ego_speed_mps,
                  const Lanes& lanes) {
  if (role.direction != Direction::kForward) return kOncomingSettle_s;
  if (role.ahead_m <= 0.0 || lanes.of(slot.direction) < 2) return 0.0;
  const double relative_mps = relative_speed_mps(slot.direction, ego_direction, slot.speed_mps, ego_speed_mps);
  return closing_speed_mps(role, relative_mps) > kSettleClosing_mps ? kSettleEarly_s : 0.0;
}

// A waypoint `time_s` from now: where `slot` is `before_s` before the start (moving at its speed),
// `ahead_m` further along its direction.
Waypoint on_track_before(const Slot& slot, double time_s, double before_s, double ahead_m) {
  Waypoint w{slot, time_s};
  w.slot.s_m += sign(slot.direction) * (ahead_m - slot.speed_mps * before_s);
  return w;
}
}  // namespace

Waypoint way_to(const Slot& slot, const Aim& aim, const PlayRoleConfig& role, Direction ego_direction, int ego_lane,
                const Lanes& lanes, double time_to_start_s, const DirectorConfig& cfg) {
  const bool beside = slot.direction == ego_direction && slot.lane != ego_lane && std::abs(role.ahead_m) <= kBesideReach_m;
  if (beside && cfg.beside_wait_ahead_m != 0.0 && time_to_start_s > cfg.beside_approach_s) {
    const double approach_s = cfg.beside_approach_s;
    return on_track_before(slot, time_to_start_s - approach_s, approach_s, cfg.beside_wait_ahead_m);
  }
  const double settle_s = settling_s(slot, role, ego_direction, aim.ego_speed_mps, lanes);
  if (settle_s > 0.0 && aim.time_s > settle_s) return on_track_before(slot, aim.time_s - settle_s, settle_s, 0.0);
  return {slot, aim.time_s};
}

SpeedBand transport_band(const Slot& slot, const DirectorConfig& cfg) {
  SpeedBand b;
  b.high_mps = slot.speed_mps + cfg.max_speed_offset_mps;
  b.low_mps = std::max(std::min(cfg.min_speed_mps, slot.speed_mps), slot.speed_mps - cfg.max_speed_offset_mps);
  return b;
}

double transport_rate_mps2(const DirectorConfig& cfg, double type_accel_mps2) {
  return type_accel_mps2 > 0.0 ? std::min(cfg.transport_rate_mps2, kRateShareOfTypeAccel * type_accel_mps2)
                               : cfg.transport_rate_mps2;
}

double needed_speed_mps(const Slot& slot, double s_m, double time_s) {
  return sign(slot.direction) * (slot.s_m - s_m) / std::max(time_s, 1e-3);
}

namespace {
constexpr int kPlanBisections = 50;

double trapezoid_distance_m(double v0, double vc, double vf, double time_s, double a) {
  const double t1 = std::abs(vc - v0) / a;
  const double t3 = std::abs(vc - vf) / a;
  return 0.5 * (v0 + vc) * t1 + vc * (time_s - t1 - t3) + 0.5 * (vc + vf) * t3;
}
}  // namespace

SpeedPlan plan_speed(double v0_mps, double v_final_mps, double time_s, double distance_m, const SpeedBand& band,
                     double rate_mps2) {
  SpeedPlan plan;
  const double a = rate_mps2;
  const double direct_s = std::abs(v_final_mps - v0_mps) / a;
  if (time_s <= direct_s) {  // no time for anything but the change to the final speed
    plan.cruise_mps = v_final_mps;
    plan.final_change_s = 0.0;
    plan.shortfall_m = distance_m - 0.5 * (v0_mps + v_final_mps) * time_s;
    if (std::abs(plan.shortfall_m) < 1e-9) plan.shortfall_m = 0.0;
    return plan;
  }
  // Cruise speeds the trapezoid can reach in time, inside the band.
  const double reach = 0.5 * a * (time_s - direct_s);
  double lo = std::max(band.low_mps, std::min(v0_mps, v_final_mps) - reach);
  double hi = std::min(band.high_mps, std::max(v0_mps, v_final_mps) + reach);
  if (lo > hi) lo = hi = std::clamp(v_final_mps, band.low_mps, band.high_mps);
  const double d_lo = trapezoid_distance_m(v0_mps, lo, v_final_mps, time_s, a);
  const double d_hi = trapezoid_distance_m(v0_mps, hi, v_final_mps, time_s, a);
  if (distance_m <= d_lo || distance_m >= d_hi) {
    const bool low = distance_m <= d_lo;
    plan.cruise_mps = low ? lo : hi;
    plan.shortfall_m = distance_m - (low ? d_lo : d_hi);
  } else {
    for (int i = 0; i < kPlanBisections; ++i) {
      const double mid = 0.5 * (lo + hi);
      (trapezoid_distance_m(v0_mps, mid, v_final_mps, time_s, a) < distance_m ? lo : hi) = mid;
    }
    plan.cruise_mps = 0.5 * (lo + hi);
  }
  plan.final_change_s = std::abs(plan.cruise_mps - v_final_mps) / a;
  return plan;
}

const ObservedVehicle* unpassable_leader(const EgoObservation& ego, const std::vector<ObservedVehicle>& world,
                                         const Lanes& lanes) {
  if (lanes.of(ego.direction) != 1 || ego.lane != 0 || ego.target_lane != 0) return nullptr;
  const int dir = sign(ego.direction);
  const ObservedVehicle* nearest = nullptr;
  for (const ObservedVehicle& v : world) {
    if (!occupies(v, ego.direction, 0) || dir * (v.s_m - ego.s_m) <= 0.0) continue;
    if (nearest == nullptr || dir * v.s_m < dir * nearest->s_m) nearest = &v;
  }
  return nearest;
}

LeaderAhead leader_ahead(const EgoObservation& ego, const ObservedVehicle& leader, double speed_mps) {
  const double gap = sign(ego.direction) * (leader.s_m - ego.s_m) - 0.5 * (leader.length_m + ego.length_m);
  return LeaderAhead{std::max(gap, 0.0), speed_mps};
}

bool occupies(const ObservedVehicle& v, Direction dir, int lane) {
  return v.direction == dir && (v.lane == lane || v.target_lane == lane);
}

bool occupies(const EgoObservation& ego, Direction dir, int lane) {
  return ego.direction == dir && (ego.lane == lane || ego.target_lane == lane);
}

bool passing(const ObservedVehicle& v, const Lanes& lanes) {
  return v.lane >= lanes.of(v.direction) || v.target_lane >= lanes.of(v.direction);
}

bool passing(const EgoObservation& ego, const Lanes& lanes) {
  return ego.lane >= lanes.of(ego.direction) || ego.target_lane >= lanes.of(ego.direction);
}

Between between(const Slot& slot, VehicleId self, double s_m, double time_s, const std::vector<ObservedVehicle>& world,
                const EgoObservation& ego, double ego_s_at_handover_m) {
  const int dir = sign(slot.direction);
  const double p_now = dir * s_m;
  const double p_then = dir * slot.s_m;
  Between b;
  for (const ObservedVehicle& v : world) {
    if (v.id == self || !occupies(v, slot.direction, slot.lane)) continue;
    const double q_now = dir * v.s_m;
    const double q_then = q_now + v.speed_mps * time_s;
    if ((q_now > p_now) != (q_then > p_then)) {
      ++b.vehicles;
      if (q_now > p_now) ++b.to_pass;
    }
  }
  // The ego moves too: what counts is whether the vehicle's order relative to it changes between
  // now and the handover (the ego at trigger point 2 then, where the slots are measured from).
  if (ego.direction == slot.direction) {
    const double ahead_now = dir * (s_m - ego.s_m);
    const double ahead_then = dir * (slot.s_m - ego_s_at_handover_m);
    b.ego = (ahead_now > 0.0) != (ahead_then > 0.0);
  }
  return b;
}

}  // namespace entourage::director
