#include "director/core/transport.hpp"

#include <algorithm>
#include <cmath>

namespace entourage::director {

namespace {
// An actor that passed the ego keeps its passing lane until this far ahead of it.
constexpr double kPassedEgoBy_m = 15.0;

int passing_lane(int lane, const Lanes& lanes, Direction dir) {
  const int n = lanes.of(dir);
  if (lane + 1 < n) return lane + 1;
  if (lane - 1 >= 0) return lane - 1;
  return lane;
}

// How far ahead a vehicle in its way holds an actor up: up to its target or kHoldsUpHorizon_s at
// its speed (or command), whichever is nearer (progress along its direction).
double hold_up_horizon_p(const ObservedVehicle& actor, double cmd_mps, double target_p) {
  const double p = sign(actor.direction) * actor.s_m;
  return std::min(target_p, p + std::max(actor.speed_mps, cmd_mps) * kHoldsUpHorizon_s);
}

}  // namespace

bool holds_up(const ObservedVehicle& v, Direction direction, int lane, double target_p, const ObservedVehicle& actor,
              double cmd_mps) {
  if (v.id == actor.id || !occupies(v, direction, lane)) return false;
  const int dir = sign(direction);
  const double q = dir * v.s_m;
  return q > dir * actor.s_m && q < hold_up_horizon_p(actor, cmd_mps, target_p) && v.speed_mps < cmd_mps - kHoldsUp_mps;
}

namespace {
// Would an actor that passes in `lane` be ahead of the ego there? An actor whose start is in
// another lane then holds the ego up: it soon slows to the pace of its start beside the ego, and
// the way back to its own lane is often blocked by the very traffic it passes (cut-in, traced:
// the cutter passed a slower car on the ego's side, waited there for the ego, and both slowed
// from 29 to 13 m/s). The ego's lane is a passing lane only behind the ego.
bool ahead_of_ego_in(int lane, const ObservedVehicle& actor, const EgoObservation& ego) {
  const int dir = sign(actor.direction);
  return occupies(ego, actor.direction, lane) && dir * actor.s_m > dir * ego.s_m;
}

// Is a vehicle that must get to `target_p` (progress along its direction) in `lane` held up there
// by something it must get past (a vehicle that holds it up, or the ego it must pass)?
bool held_up(Direction direction, int lane, double target_p, const ObservedVehicle& actor, double cmd_mps,
             const std::vector<ObservedVehicle>& world, const EgoObservation& ego) {
  const int dir = sign(direction);
  const double p = dir * actor.s_m;
  if (target_p <= p) return false;  // it falls back: followers pass it
  for (const ObservedVehicle& v : world) {
    if (holds_up(v, direction, lane, target_p, actor, cmd_mps)) return true;
  }
  if (occupies(ego, direction, lane)) {
    const double q = dir * ego.s_m;
    const bool passing = actor.lane != lane;  // already beside: until it is well past
    if (q > p - (passing ? kPassedEgoBy_m : 0.0) && q < hold_up_horizon_p(actor, cmd_mps, target_p)) return true;
  }
  return false;
}
}  // namespace

double command_fall_rate_mps2(double ego_accel_mps2, double from_ego_m) {
  if (from_ego_m >= kCommandFallWithEgoWithin_m) return kCommandRate_mps2;
  return std::clamp(-ego_accel_mps2, kCommandRate_mps2, kCommandFallWithEgoMax_mps2);
}

double drive_speed_mps(double speed_mps, double actor_speed_mps, double rate_mps2, double type_accel_mps2) {
  if (type_accel_mps2 <= 0.0 || speed_mps <= actor_speed_mps) return speed_mps;
  const double share = std::min(rate_mps2 / type_accel_mps2, kMaxDriveShare);
  return std::max(speed_mps, actor_speed_mps / std::pow(1.0 - share, 0.25));
}

double ego_pace_floor_mps(double ahead_of_ego_m, double start_ahead_m, double ego_speed_mps, double start_offset_mps) {
  if (ahead_of_ego_m <= 0.0 || ahead_of_ego_m >= start_ahead_m) return -1.0;
  const double open_mps = std::min((start_ahead_m - ahead_of_ego_m) / kOpenToStart_s, kOpenToStartMax_mps);
  return std::max(0.0, ego_speed_mps + start_offset_mps) + open_mps;
}

double start_speed_floor_mps(double ahead_of_ego_m, double start_ahead_m, double tolerance_m, double start_speed_mps) {
  if (ahead_of_ego_m <= 0.0 || ahead_of_ego_m > start_ahead_m + tolerance_m) return -1.0;
  const double open_mps =
      ahead_of_ego_m < start_ahead_m ? std::min((start_ahead_m - ahead_of_ego_m) / kOpenToStart_s, kOpenToStartMax_mps) : 0.0;
  return std::max(0.0, start_speed_mps) + open_mps;
}

TransportCommand transport(const Slot& slot, const ObservedVehicle& actor, double time_left_s, double previous_cmd_mps,
                           double dt_s, const std::vector<ObservedVehicle>& world, const EgoObservation& ego,
                           const Lanes& lanes, const DirectorConfig& cfg, double rate_mps2, double type_accel_mps2) {
  const int dir = sign(slot.direction);
  const double t = std::max(time_left_s, 0.0);
  const SpeedPlan plan =
      plan_speed(actor.speed_mps, slot.speed_mps, t, dir * (slot.s_m - actor.s_m), transport_band(slot, cfg),
                 rate_mps2);
  TransportCommand c;
  c.position_error_m = plan.shortfall_m;
  c.speed_error_mps = actor.speed_mps - slot.speed_mps;
  const double target = t <= plan.final_change_s + dt_s ? slot.speed_mps : plan.cruise_mps;
  const double from = previous_cmd_mps >= 0.0 ? previous_cmd_mps : actor.speed_mps;
  const double up = kCommandRate_mps2 * dt_s;
  const double down = command_fall_rate_mps2(ego.accel_mps2, std::abs(actor.s_m - ego.s_m)) * dt_s;
  c.speed_mps = std::max(0.0, std::clamp(target, from - down, from + up));
  c.drive_mps = drive_speed_mps(c.speed_mps, actor.speed_mps, rate_mps2, type_accel_mps2);
  // Held up on the way: a neighbouring lane to get past, kept until it is past.
  c.lane = slot.lane;
  if (held_up(slot.direction, slot.lane, dir * slot.s_m, actor, c.speed_mps, world, ego)) {
    const int pass = actor.lane == slot.lane ? passing_lane(slot.lane, lanes, slot.direction) : actor.lane;
    // Only by a lane in which it is not held up as well (the ego, or a queue, ahead of it there).
    if (!held_up(slot.direction, pass, dir * slot.s_m, actor, c.speed_mps, world, ego) &&
        (pass == slot.lane || !ahead_of_ego_in(pass, actor, ego))) {
      c.lane = pass;
    }
  }
  return c;
}

}  // namespace entourage::director
