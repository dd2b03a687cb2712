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
// the ego, or a queue); the vehicles in its way are asked to make way (make_way).
//
// Clear zones: a vehicle that would be inside a zone at the start (at its present speed) is asked
// to leave: to a neighbouring lane that is no zone's, or to be ahead of the zone or behind it at
// the start by a speed within the band around its own, planned to be out a few seconds early
// (not on one lane per direction: there it would have to overtake or be overtaken, which is left
// to its own driving). A vehicle cleared off a zone or out of an actor's way that waits to change
// lanes is let in by the vehicle just behind it in the target lane (follower_to_let_in).

#include <optional>
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

// A zone at the handover, in road s, in one lane of the ego's direction, with the ego at
// `ego_s_m` (trigger point 2 while preparing; where it is at the handover).
struct ZoneAtStart {
  Direction direction = Direction::kForward;
  int lane = 0;
  double from_s_m = 0.0;  // lower s
  double to_s_m = 0.0;    // higher s
};
std::vector<ZoneAtStart> zones_of(const PlayConfig& play, Direction ego_direction, int ego_lane, double ego_s_m,
                                  const Lanes& lanes);

// The room each actor of the ego's direction needs at its start, besides the play's own zones:
// its length, kSlotGapBehind_m behind it and a safe headway ahead (kSlotMinGap_m plus
// kSlotTimeGap_s at the slot's speed). A vehicle there keeps an actor that must change into the
// lane from getting in (and would stand between it and the ego). Cleared, not checked at the
// handover. `lengths_m[i]`: the length of slot i's actor.
inline constexpr double kSlotGapBehind_m = 2.0;
inline constexpr double kSlotMinGap_m = 5.0;
inline constexpr double kSlotTimeGap_s = 1.0;
// The ego's leader may move into a lane ahead of an actor that starts there faster than its type
// drives this long before the start at most (ahead_in_next_lane), if the ego follows it within
// kFollowedSpeedBand_mps and the actor will be within kActorInPlace_m of its start. (12 s until
// stop 54: once its leader has left, the ego speeds up, and the actor's start speed, relative to
// the ego's, with it; moved over 12 s early, a truck held the cutter behind it below that speed.)
inline constexpr double kLateMoveWindow_s = 6.0;
inline constexpr double kFollowedSpeedBand_mps = 1.0;
inline constexpr double kActorInPlace_m = 10.0;
std::vector<ZoneAtStart> slot_zones(const std::vector<Slot>& slots, const std::vector<double>& lengths_m,
                                    Direction ego_direction);

// Where `v` is `t_s` from now at its present speed (road s).
inline double s_after_m(const ObservedVehicle& v, double t_s) { return v.s_m + sign(v.direction) * v.speed_mps * t_s; }

// Does a vehicle of length `length_m` with its centre at `s_m` in `lane` overlap a zone?
bool in_zone(const ZoneAtStart& z, int lane, double s_m, double length_m);
// The first zone `v` overlaps with its centre at `s_m` (in either lane it occupies), or nullptr.
const ZoneAtStart* zone_hit(const std::vector<ZoneAtStart>& zones, const ObservedVehicle& v, double s_m);

// `zone` with every zone of its lane that comes within `gap_m` of it (repeatedly): the stretch a
// vehicle must be ahead of or behind, since it cannot stand between them.
ZoneAtStart joined_zone(const ZoneAtStart& zone, const std::vector<ZoneAtStart>& zones, double gap_m);

// What a vehicle that would stand in a zone at the start is asked to do, if anything can help.
//
// A vehicle ahead of the ego in the ego's lane cannot get out of a zone ahead of the ego by its
// speed alone: the ego's driver closes up behind it at whatever speed it drives (up to the ego's
// own desired speed), and its own leader holds it in the queue the ego follows. It changes into a
// neighbouring lane that an actor needs instead, when it can be ahead of every zone of that lane
// by the start at a speed within the band, is ahead of that lane's actors now (it never has to get
// past one), no actor behind it there catches up with it before the start at their present
// speeds (it would hold that actor up on its way) and none starts there faster than any driver of
// its type wishes to drive, less 1 m/s (a truck sent ahead of the cutter was caught once the ego
// sped up, stops 45 and 50; ClearingSituation::slots), unless, in the last kLateMoveWindow_s, the
// ego follows it at its speed and that actor is in place already (stop 46): onto the free lane
// first, then into such a lane, then by its speed in its own. Never into a lane where an actor is
// alongside it (from just behind it to the room the actor keeps ahead): it would cut in on the
// actor; onto the free lane, though, where that actor waits in place to move into v's lane
// (ActorPlace::waits_for_lane): the two swap lanes, the actor letting v in.
struct ActorPlace {
  int lane = 0;
  double s_m = 0.0;
  double speed_mps = 0.0;
  double length_m = 4.5;  // the actor's
  int waits_for_lane = -1;  // lane_waited_for
};
struct Clearance {
  double speed_mps = 0.0;  // desired speed (kOwnDesiredSpeed_mps: its own, when it only changes lane)
  int lane = -1;
};
struct ClearingSituation {
  const std::vector<ZoneAtStart>& zones;
  double time_left_s = 0.0;             // until the time the zones are for
  const EgoObservation& ego;
  double ego_s_then_m = 0.0;            // where the ego is then
  const std::vector<Slot>& slots;       // the roles' start places (the lanes they need: those of the ego's direction)
  const Lanes& lanes;
  const DirectorConfig& cfg;
  std::vector<ActorPlace> actors = {};  // where the actors of the ego's direction are now
  TypeTable types = {};                 // the vehicle types' drivers (stage.hpp): none asked above its top speed
};
std::optional<Clearance> clear_out(const ObservedVehicle& v, const ClearingSituation& at);

// The lane of its start that an actor in place beside it waits to move into: in another lane of
// its direction than the start's, not moving over yet, and within kActorInPlace_m of its start by
// then at its present speed (`time_left_s` from now); -1 otherwise. A vehicle of the director's in
// its room in that lane may move into the actor's lane, the actor letting it in (the two swap
// lanes; PlayRun::let_in): kept apart, a truck at its type's top speed that the ego followed stood
// in the lead's room, and the lead beside it waited until the handover failed (lead vehicle, seeds
// 9, 37 and 66, stop 67). Not one still on its way to its place: let in ahead of it, a truck that
// the ego followed at 19 m/s held it back (seed 208).
int lane_waited_for(const ObservedVehicle& actor, const Slot& start, double time_left_s);

// A vehicle that holds an actor up on its way to its slot (in the slot's lane, ahead of the actor
// within kHoldsUpHorizon_s at its speed and not beyond the slot, slower than the actor's command by
// kHoldsUp_mps) is asked to make way: to a neighbouring lane that is no actor's and where it stands
// clear of every zone at the start, at the actor's command (`actor_cmd_mps`; the caller caps it at
// the top speed of the vehicle's type), not at its own speed: asked only to change lanes, it
// dropped back in its lane to find a gap behind slower traffic there (gap seeking,
// traffic/lane_changes.hpp) and held the actor up behind it (cut-in, seeds 1-400: the cutter held
// up 10 s or more in 38 of the 46 failures, mostly by vehicles of the director's; stop 65). It
// keeps that pace once it has moved over, until the handover, as every cleared vehicle keeps its
// last command (back at its own speed once over: 523 of seeds 1-600 against 529, NOTES.md stop 65).
// Nothing if there is none. Never into the lane the actor is in, moving to, or was told to take
// (`actor_cmd_lane`, -1: none): an actor held up passes in a neighbouring lane (transport), and a
// vehicle asked at the same time to make way into that lane stood in front of it there (stopped
// vehicle, seed 13: the stopper boxed in behind two vehicles cleared at 24 m/s, 22 m short of its
// start).
std::optional<Clearance> make_way(const ObservedVehicle& v, const Slot& slot, const ObservedVehicle& actor,
                                  double actor_cmd_mps, int actor_cmd_lane, const ClearingSituation& at);

// One lane request per cleared vehicle. Several rules ask cleared vehicles to change lanes
// (clear_out, make_way, letting in), each from the situation of the moment, and they answered each
// other: over 50 cut-in runs 6906 of 7237 requested lane changes were undone within 5 s, and a
// driver in view signalled and then stayed, 38 times per vehicle-hour against the autonomous
// drivers' 3 (services/director/NOTES.md, stop 32). A vehicle asked for a lane
// change keeps that request while it waits to move over, for kHoldLaneRequest_s, whatever another
// rule asks of it meanwhile (its speed included), and for good once it moves.
inline constexpr double kHoldLaneRequest_s = 20.0;
struct LaneRequest {
  int lane = -1;         // the lane it was asked to change into
  double since_s = 0.0;  // when it was first asked for it
};
// Whether `v`, asked for `asked`, keeps that request instead of being asked for `lane` at `now_s`
// (false when `lane` is the one asked for, or `v` is there already).
bool keeps_lane_request(const ObservedVehicle& v, const LaneRequest& asked, int lane, double now_s);

// Letting in: a vehicle asked to change lanes at its own speed that still waits in its lane
// (indicator on) is let in, as drivers let in one who signals: the vehicle just behind it in the
// target lane (its front behind the waiting one's front, its gap to that one's rear less than
// kLetInReach_s at its own speed or kLetInQueueReach_m; overlapping counts, except beside one
// that nearly stands, which it could not fall behind) is asked to hold back kLetIn_mps below the
// waiting one's speed until it has moved over. In dense traffic the lane the vehicles are cleared
// into has no gap wide enough at its speed, and one that waited for a gap fell ever further below
// that speed (gap_seeking_cap_mps2), with the vehicles behind it, the ego among them.
inline constexpr double kLetInReach_s = 2.5;
// In a slow or standing queue, the one queued just behind (its gap less than this) lets it in.
inline constexpr double kLetInQueueReach_m = 10.0;
inline constexpr double kLetIn_mps = 2.0;
// A waiting vehicle slower than kLetIn_mps: one holding back kLetIn_mps below it stands, and
// beside it would stand there with it for good.
inline bool nearly_stands(const ObservedVehicle& waiting) { return waiting.speed_mps < kLetIn_mps; }
// The vehicle that would let `waiting` into `lane`, if any (nullptr: none close enough, or the
// ego is the one just behind it there).
const ObservedVehicle* follower_to_let_in(const ObservedVehicle& waiting, int lane,
                                          const std::vector<ObservedVehicle>& world, const EgoObservation& ego);

}  // namespace entourage::director
