#pragma once
// Clearing the stage (paper IV: moving unwanted vehicles away) with the behaviour of everyday
// drivers, as transport.hpp moves the actors.
//
// Clear zones: a vehicle that would be inside a zone at the start (zones.hpp; at its present
// speed) is asked to leave: to a neighbouring lane that is no zone's, or to be ahead of the zone
// or behind it at the start by a speed within the band around its own, planned to be out a few
// seconds early (not on one lane per direction: there it would have to overtake or be overtaken,
// which is left to its own driving). A vehicle that holds an actor up on its way is asked to make
// way. A vehicle cleared off a zone or out of an actor's way that waits to change lanes is let in
// by the vehicle just behind it in the target lane (follower_to_let_in).
//
// Each rule here judges one vehicle from the situation of the moment; PlayRun (play_clearing.cpp)
// applies them to the traffic at each step and keeps each vehicle's lane request.

#include <optional>
#include <vector>

#include "director/core/stage.hpp"
#include "director/core/zones.hpp"

namespace entourage::director {

// The ego's leader may move into a lane ahead of an actor that starts there faster than its type
// drives this long before the start at most (ahead_in_next_lane), if the ego follows it within
// kFollowedSpeedBand_mps and the actor will be within kActorInPlace_m of its start. (12 s until
// stop 54: once its leader has left, the ego speeds up, and the actor's start speed, relative to
// the ego's, with it; moved over 12 s early, a truck held the cutter behind it below that speed.)
inline constexpr double kLateMoveWindow_s = 6.0;
inline constexpr double kFollowedSpeedBand_mps = 1.0;
inline constexpr double kActorInPlace_m = 10.0;

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
// Whether `follower`, holding back at `hold_mps` to let one in, would hold up an actor on its way to
// its start (`actor_cmd_mps`: the actor's command): in the start's lane, ahead of the actor there,
// the actor still behind its start, within kHoldsUpHorizon_s of it at its speed or command (beyond
// the start too: the vehicles between slow down with it) and `hold_mps` below that command by
// kHoldsUp_mps (holds_up, transport.hpp). Such a follower does not let the waiting one in. (Traced,
// cut-in seed 243, stop 68: a car 51 m ahead of the ego in the cutter's lane held back to 23 m/s for
// a cleared car that waited to move in ahead of it; the car beside the ego, and the cutter behind
// both, slowed with it, and the cutter never got past the ego.)
bool held_back_holds_up(const ObservedVehicle& follower, double hold_mps, const Slot& start,
                        const ObservedVehicle& actor, double actor_cmd_mps);

}  // namespace entourage::director
