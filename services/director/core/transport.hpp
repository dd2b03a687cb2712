#pragma once
// Transportation (paper IV): moving actors to their start positions by the estimated start time,
// with the behaviour of everyday drivers. The director only sets what the actor's own driver
// model aims for (traffic/actor_control.hpp); the model keeps it safe and smooth.
//
// Speed: each step the actor's way to the slot is planned again (stage.hpp, plan_speed): change
// to a cruise speed, cruise, change to the slot's speed just in time, at the director's transport
// rate (the slot of a role slower than the ego ahead of it is a waypoint on its start's track
// kSettleEarly_s before the start: stage.hpp, way_to). The actor is
// given the cruise speed as its desired speed, then the slot's speed once the final change is
// due; the desired speed moves by at most kCommandRate per second (falls faster while the ego
// brakes: command_fall_rate_mps2), so the driver model eases into it instead of jumping (the
// plan's rate is lower than that, for the driver's lag).
//
// Lane: the slot's lane, except that an actor that must get past a slower vehicle in that lane
// (or past the ego) first takes a neighbouring lane, if it is not held up there as well (behind
// the ego, or a queue); the vehicles in its way are asked to make way (make_way, clearing.hpp).

#include <vector>

#include "director/core/stage.hpp"
#include "traffic/actor_control.hpp"

namespace entourage::director {

// How fast the desired speed given to an actor may change (above the plan's rate,
// DirectorConfig::transport_rate_mps2, which leaves room for the driver's lag).
inline constexpr double kCommandRate_mps2 = 1.0;
// While the ego brakes harder than that, the desired speed of an actor near it (within
// kCommandFallWithEgoWithin_m, ahead or behind: a driver who sees it brake) may fall as fast as the
// ego slows down, up to what a car's driver brakes at comfortably (IDM's b, some 2 m/s^2): the
// start moves with the ego, and an actor slowing more gently overshoots it. Traced, cut-in seed 5
// (stop 64): the ego braked from 28.6 to 17 m/s at 1.5 m/s^2 while the cutter came up 42 m behind
// in the next lane at 35 m/s; slowing at 1 m/s^2 it passed the ego and ran up to 113 m ahead of its
// start, which the plan, within 8 m/s of the start speed, could not win back by trigger point 2.
// Not further away: a cutter 190 m behind the ego that slowed with it was left behind in the
// ego's lane when the ego sped up again (seed 305).
inline constexpr double kCommandFallWithEgoMax_mps2 = 2.0;
inline constexpr double kCommandFallWithEgoWithin_m = 100.0;
// `from_ego_m`: the actor's distance from the ego along the road.
double command_fall_rate_mps2(double ego_accel_mps2, double from_ego_m);

struct TransportCommand {
  double speed_mps = 0.0;     // the speed the actor should drive at now (rate-limited plan)
  double drive_mps = 0.0;     // the desired speed given to its driver model for that (drive_speed_mps)
  int lane = -1;              // lane to reach
  double position_error_m = 0.0;  // where the plan brings it at the start: > 0 behind the slot
  double speed_error_mps = 0.0;   // actor's speed - the slot's speed
};

// A driver model approaches its desired speed ever more slowly (IDM's free road: a (1 - (v/v0)^4)),
// so an actor given the speed it should reach would lag its plan more and more. To speed up at
// `rate_mps2` it is given the desired speed at which its free-road acceleration is that rate,
// (v / (1 - rate/a)^(1/4), `a` its type's mean acceleration, the share capped at
// kMaxDriveShare), never below `speed_mps`; at or above it, `speed_mps` itself.
inline constexpr double kMaxDriveShare = 0.8;
double drive_speed_mps(double speed_mps, double actor_speed_mps, double rate_mps2, double type_accel_mps2);

// An actor ahead of the ego in the ego's lane, nearer to it than its start (`start_ahead_m`, at a
// speed relative to the ego's, `start_offset_mps`), is already where the play wants it relative to
// the ego: it drives at least at its start speed relative to the ego now, opening the gap to its
// start over kOpenToStart_s (at most kOpenToStartMax_mps faster). Paced by the plan instead, it
// held the ego up, which moved the estimated start later and its plan slower with it (traced,
// lead vehicle seed 41, stop 30: the lead 20-40 m ahead, both from 29 to 1 m/s in 50 s). Below 0:
// no floor (elsewhere, or already beyond its start).
inline constexpr double kOpenToStart_s = 10.0;
inline constexpr double kOpenToStartMax_mps = 2.0;
double ego_pace_floor_mps(double ahead_of_ego_m, double start_ahead_m, double ego_speed_mps, double start_offset_mps);
// The same for a role with an absolute start speed (a slow truck at 60 km/h): within its position
// tolerance of its start relative to the ego, or nearer, it drives at least at its start speed
// (opening the gap as above when nearer). Paced by the plan instead, the ego behind it held up by
// it moved the estimated start later and the plan slower with it (traced, slow truck seed 60,
// stop 35: the truck, a car that had cut in and the ego from 20 to 8.6 m/s in 60 s).
double start_speed_floor_mps(double ahead_of_ego_m, double start_ahead_m, double tolerance_m, double start_speed_mps);

// `previous_cmd_mps`: the speed of the previous step's command (< 0: none yet).
// `rate_mps2`: the planning rate (transport_rate_mps2 for the actor's type); `type_accel_mps2`:
// the type's mean acceleration (0: unknown, no lead on the desired speed).
TransportCommand transport(const Slot& slot, const ObservedVehicle& actor, double time_left_s, double previous_cmd_mps,
                           double dt_s, const std::vector<ObservedVehicle>& world, const EgoObservation& ego,
                           const Lanes& lanes, const DirectorConfig& cfg, double rate_mps2, double type_accel_mps2);

// A vehicle in the slot's lane slower than the actor's command by this much holds it up...
inline constexpr double kHoldsUp_mps = 1.0;
// ...if it is ahead of the actor by less than this many seconds at its speed or command.
inline constexpr double kHoldsUpHorizon_s = 8.0;
// Does `v` hold up an actor that must get to `target_p` (progress along its direction) in `lane`:
// ahead of it there, within kHoldsUpHorizon_s at the actor's speed or command `cmd_mps` and not
// beyond the target, slower than the command by kHoldsUp_mps? (transport passes it; make_way asks
// it out of the way.)
bool holds_up(const ObservedVehicle& v, Direction direction, int lane, double target_p, const ObservedVehicle& actor,
              double cmd_mps);

}  // namespace entourage::director
