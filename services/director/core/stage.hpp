#pragma once
// Where a play's roles must be at the handover, and the geometry the director reasons in.
// Positions are road s; "travel" coordinates are progress along a vehicle's own direction
// (sign(direction) * s), so ahead is larger for both directions.

#include <limits>
#include <optional>
#include <vector>

#include "director/core/start_time.hpp"
#include "road/window.hpp"
#include "scenario/config.hpp"
#include "traffic/world.hpp"

namespace entourage::director {

// A role's start: lane, position and speed at the handover.
struct Slot {
  Direction direction = Direction::kForward;
  int lane = 0;
  double s_m = 0.0;       // centre at the handover
  double speed_mps = 0.0;
};

// The roads's lanes per direction.
struct Lanes {
  int forward = 1;
  int backward = 0;
  int of(Direction d) const { return d == Direction::kForward ? forward : backward; }
};

// What the director knows of a vehicle type's drivers (from the scenario's vehicle types), per
// type index.
struct TypeTraits {
  double accel_mps2 = 0.0;  // their mean maximum acceleration (0: unknown)
  bool overtakes = true;    // they overtake in the oncoming lane (lane_change "overtaking")
  double top_speed_mps = 0.0;  // the highest desired speed any of them has (0: unknown)
};
using TypeTable = std::vector<TypeTraits>;
// A type not in the table: acceleration unknown, and taken to overtake.
inline double accel_of(const TypeTable& types, std::uint8_t type_index) {
  return type_index < types.size() ? types[type_index].accel_mps2 : 0.0;
}
inline bool overtakes_of(const TypeTable& types, std::uint8_t type_index) {
  return type_index >= types.size() || types[type_index].overtakes;
}
// The highest desired speed the director gives a vehicle of the type (infinite where unknown).
inline double top_speed_of(const TypeTable& types, std::uint8_t type_index) {
  const double top = type_index < types.size() ? types[type_index].top_speed_mps : 0.0;
  return top > 0.0 ? top : std::numeric_limits<double>::infinity();
}

// The lane of the ego's direction a play is staged beside: the lane the ego is in or moving to,
// or, while it overtakes in an oncoming lane (a lane index beyond its direction's lanes), the
// lane of its own direction nearest to it, where it comes back (a staging that followed it out
// dropped the clear zones, and a truck's actor was recast beyond the one just cast).
int staging_lane(const EgoObservation& ego, const Lanes& lanes);

// The play as staged beside an ego in `ego_lane`: unchanged if every lane it uses relative to the
// ego (forward roles, clear zones) exists; otherwise, if the mirror image fits, mirrored: those
// lane offsets and its scripted lane changes negated, left and right indicators swapped (a car
// that cuts in from the left of an ego in the left lane cuts in from the right).
PlayConfig staged_beside(const PlayConfig& play, int ego_lane, const Lanes& lanes);
// Whether staged_beside mirrors `play` beside an ego in `ego_lane`.
bool mirrored_beside(const PlayConfig& play, int ego_lane, const Lanes& lanes);

// When and where the actors are aimed at: the ego at `ego_s_m` with `ego_speed_mps`, `time_s`
// from now, which is `past_start_s` after the start (the handover). Until the last seconds before
// the start that is the ego at trigger point 2 at the estimated start; closer to it, and while
// the handover waits beyond trigger point 2, a short horizon ahead (aim_of), so that the actors
// keep closing on their places instead of holding a plan that has run out of time.
struct Aim {
  double time_s = 0.0;
  double ego_s_m = 0.0;
  double ego_speed_mps = 0.0;
  double past_start_s = 0.0;
};

// `time_to_start_s`: estimated (0 once the ego is beyond trigger point 2); `speed_at_start_mps`:
// the ego's estimated speed there. Within `horizon_s` of the start the ego is taken to drive on at
// its present speed.
Aim aim_of(double time_to_start_s, double trigger2_s_m, double speed_at_start_mps, const EgoObservation& ego,
           double horizon_s);

// A role's start speed with the ego at `ego_speed_mps`: its own (absolute), or the ego's plus its
// offset, never below standing.
double start_speed_mps(const PlayRoleConfig& role, double ego_speed_mps);

// Actors are aimed late rather than early. The ego closes on some roles: a slower one ahead of it
// (the stopped vehicle's at 80 km/h, the slow truck), an oncoming one (at the sum of both speeds),
// a faster one behind it. An ego a second later at trigger point 2 than the last estimate finds
// such a role that much nearer than its start, and the handover may wait for an actor still too
// far (handover_wait_s), never for one already too near: the ego only comes nearer. So the play is
// aimed `late_aim_s` late: each such role's slot lies as far beyond its start as the ego closes on
// it in that time. The time is the one that puts the role with the least room for it
// kLateShare of its position tolerance beyond its start (the oncoming cars of the slow truck,
// 25 of 50 m; the truck then some 4 of 15 m); where the ego comes as estimated every actor is
// within its tolerance, and one a moment early waits for them. Roles the ego does not close on
// (the lead vehicle at the ego's speed, the cutter 5 km/h faster) are aimed at their start.
inline constexpr double kLateShare = 0.5;
// That time (s) with the ego at `ego_speed_mps`; 0 where the ego closes on none of the roles.
double late_aim_s(const PlayConfig& play, Direction ego_direction, double ego_speed_mps);

// The slots of `play`'s roles at `aim`, the ego in `ego_lane`. A role stands `ahead_m` from the
// ego at the start and drives on at its start speed: at a time past the start it is that much
// further ahead or behind. Forward means the ego's direction.
std::vector<Slot> slots_of(const PlayConfig& play, Direction ego_direction, int ego_lane, const Aim& aim,
                           const Lanes& lanes);

// Where an actor is aimed on its way. A role of the ego's direction in another lane and within
// kBesideReach_m of the ego at the start (a car that cuts in) would otherwise, once cast near the
// ego, drive beside it for a minute or more: a driver notices a car that paces them, and it keeps
// them out of that lane. Until `beside_approach_s` before the start it is aimed
// `beside_wait_ahead_m` ahead of its start (negative: behind): its way leads to where its start is
// `beside_approach_s` before the start (moving at the start's speed), that much further ahead, by
// then; in the last seconds the ego comes up to it (or it to the ego) by a few m/s.
//
// A role of the ego's direction ahead of it that the ego closes on by more than
// kSettleClosing_mps (the stopper at 80 km/h) settles early: its way leads to where its start is
// kSettleEarly_s before the start (moving at the start's speed), by then, and it drives at its
// start speed for the last kSettleEarly_s. Planned to change to that speed just in time, it drove
// at about the ego's speed until the last seconds, and any slower vehicle ahead of it in its lane
// then held it back where it could not make up the ground (stopped vehicle, seed 128, stop 51:
// held to 24 m/s by cleared trucks waiting to move over while asked for 36, 24 m short of its
// start); at its start speed the traffic ahead of it is faster. Only with a lane of its direction
// beside it: on one lane per direction the traffic behind it queues for those seconds (the slow
// truck lost 25 runs and gained 4 of 155 settled early, stop 52). An actor that cannot reach
// that track in time misses by as much at the waypoint, and is given up and cast again as any
// actor that misses by far (a better placed one is found; judged by its miss at the start
// instead, the stopped vehicle lost 19 runs of 200, stop 52).
//
// An oncoming role settles early as well, kOncomingSettle_s before the start. The oncoming traffic
// on a rural road comes in platoons (the generator's observed stream: vehicles held up behind
// slower ones), and an oncoming actor is often cast at the head of one, or in it: planned to change
// to its start speed just in time, one that came early waited at the band's low edge and sped up in
// the last seconds, and the platoon behind it, other oncoming actors among them, lagged its
// speed-up and met the ego 15-22 km/h too slow (slow truck, seed 92: oncoming 1 at 56 km/h 9 s
// before the start, oncoming 2 and 3, the fourth and the eighth car behind it, at 60 and 63 km/h at
// the start, where 80 was asked). Settled early, the platoon has those seconds to be back at its
// speed (services/director/README.md, *Stop 62*).
//
// Other roles, and every role after these times: the slot by the aim's time.
inline constexpr double kBesideReach_m = 30.0;
inline constexpr double kSettleEarly_s = 10.0;
inline constexpr double kSettleClosing_mps = 1.0;
inline constexpr double kOncomingSettle_s = 15.0;
struct Waypoint {
  Slot slot;
  double time_s = 0.0;  // from now
};
Waypoint way_to(const Slot& slot, const Aim& aim, const PlayRoleConfig& role, Direction ego_direction, int ego_lane,
                const Lanes& lanes, double time_to_start_s, const DirectorConfig& cfg);



// The speeds an actor may drive at on its way to `slot` (never further from the slot's speed
// than the director allows, never below its minimum unless the slot itself is slower).
struct SpeedBand {
  double low_mps = 0.0;
  double high_mps = 0.0;
  bool contains(double v) const { return v >= low_mps && v <= high_mps; }
  double clamp(double v) const { return v < low_mps ? low_mps : (v > high_mps ? high_mps : v); }
};
SpeedBand transport_band(const Slot& slot, const DirectorConfig& cfg);

// The rate an actor's speed changes are planned with: the director's, but at most a share of what
// its type's drivers accelerate at on average (a truck's 0.6 m/s^2 cannot follow a 0.7 plan).
inline constexpr double kRateShareOfTypeAccel = 0.6;
double transport_rate_mps2(const DirectorConfig& cfg, double type_accel_mps2);

// The average speed that brings a vehicle at `s_m` to the slot in `time_s` (in its direction).
double needed_speed_mps(const Slot& slot, double s_m, double time_s);

// How a vehicle at speed v0 gets `distance_m` further in `time_s` and arrives at speed v_f: it
// changes speed to a cruise speed v_c at a constant rate a, cruises, and changes to v_f at the
// same rate just in time (a trapezoid):
//
//   D(v_c) = (v0 + v_c)/2 |v_c - v0|/a + v_c t_cruise + (v_c + v_f)/2 |v_c - v_f|/a
//   t_cruise = time_s - |v_c - v0|/a - |v_c - v_f|/a >= 0
//
// D grows with v_c, so the cruise speed is found by bisection inside the band. When no cruise
// speed in the band covers the distance, the nearest one is taken and `shortfall_m` says by how
// much the vehicle will miss (> 0: it arrives behind the slot).
struct SpeedPlan {
  double cruise_mps = 0.0;
  double final_change_s = 0.0;  // duration of the change from the cruise speed to v_f at the end
  double shortfall_m = 0.0;
  bool feasible() const { return shortfall_m == 0.0; }
};
SpeedPlan plan_speed(double v0_mps, double v_final_mps, double time_s, double distance_m, const SpeedBand& band,
                     double rate_mps2);

// What stands between a vehicle at `s_m` and its slot `time_s` from now: the vehicles in the
// slot's lane whose order relative to it must change (ahead of it now and, driving on at their
// speed, behind the slot then, or the other way round: it must get past them or let them pass),
// and whether its order relative to the ego must change (the ego then at `ego_s_at_handover_m`).
struct Between {
  int vehicles = 0;   // whose order changes either way
  int to_pass = 0;    // of which it must get past (ahead of it now, behind it then)
  bool ego = false;   // its order relative to the ego changes
};
Between between(const Slot& slot, VehicleId self, double s_m, double time_s, const std::vector<ObservedVehicle>& world,
                const EgoObservation& ego, double ego_s_at_handover_m);

// The vehicle the ego follows where it cannot get past it by a lane of its own direction (one
// lane per direction: a pass in the oncoming lane is the driver's exception), for the start-time
// estimate (start_time.hpp): the nearest vehicle ahead in the ego's lane. None (nullptr) on roads
// with more lanes in the ego's direction, while the ego is out of its direction's lanes
// (overtaking), or with nobody ahead.
const ObservedVehicle* unpassable_leader(const EgoObservation& ego, const std::vector<ObservedVehicle>& world,
                                         const Lanes& lanes);
// `leader` as the estimate sees it: the gap bumper to bumper, at `speed_mps`.
LeaderAhead leader_ahead(const EgoObservation& ego, const ObservedVehicle& leader, double speed_mps);

// Does `v` (or the ego) occupy `lane` of direction `dir` (its lane or, while changing, its target
// lane)?
bool occupies(const ObservedVehicle& v, Direction dir, int lane);
bool occupies(const EgoObservation& ego, Direction dir, int lane);
// Is `v` (or the ego) passing: in an oncoming lane (a lane index beyond its direction's lanes), or
// moving into one?
bool passing(const ObservedVehicle& v, const Lanes& lanes);
bool passing(const EgoObservation& ego, const Lanes& lanes);

}  // namespace entourage::director
