#pragma once
// One play from trigger point 1 to the release of its actors (the theatre metaphor of paper III):
//
//   waiting       until the ego passes trigger point 1
//   preparing     estimating the start time; casting roles (existing vehicles, else new ones
//                 created out of sight), recast when an actor is lost
//   cast          every role has an actor
//   transporting  actors on their way to their start positions, vehicles cleared off the zones
//   handed over   the ego passed trigger point 2 and every role is in place (within tolerance),
//                 no other vehicle in a clear zone; beyond trigger point 2 the actors keep
//                 closing on their places for at most handover_wait_s until that holds
//   running       the first scripted action started
//   done          the end condition held; actors released (back to everyday driving over release_s)
//   failed        the start condition was not met by then (the reason says which role or zone);
//                 released
//
// Each step: observe the ego; act on the phase; say what changed. Commands are only written when
// a vehicle's control changes.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "director/core/casting.hpp"
#include "director/core/clearing.hpp"
#include "director/core/recent_top.hpp"
#include "director/core/script.hpp"
#include "director/core/stage.hpp"
#include "director/core/start_time.hpp"
#include "director/core/transport.hpp"
#include "traffic/actor_control.hpp"
#include "traffic/handoff.hpp"
#include "traffic/vehicle.hpp"

namespace entourage::director {

enum class PlayPhase : std::uint8_t {
  kWaiting = 0,
  kPreparing = 1,
  kCast = 2,
  kTransporting = 3,
  kHandedOver = 4,
  kRunning = 5,
  kDone = 6,
  kFailed = 7,
};

const char* to_string(PlayPhase p);

struct PlayReport {
  std::uint32_t play_id = 0;
  std::string name;
  PlayPhase phase = PlayPhase::kWaiting;
  double ego_s_m = 0.0;
  double trigger1_s_m = 0.0;
  double trigger2_s_m = 0.0;
  double estimated_start_time_s = -1.0;  // simulated time the ego is expected at trigger point 2
  std::uint16_t actors = 0;               // roles with an actor
  std::uint16_t created = 0;              // actors the director created
  std::uint16_t cleared = 0;              // vehicles asked to leave a clear zone
  double position_error_m = 0.0;          // largest over the roles (transport: to the virtual point)
  double speed_error_mps = 0.0;           // largest over the roles
  std::string detail;
};

// Makes the vehicles the director creates: ids, drivers, type.
class VehicleFactory {
 public:
  virtual ~VehicleFactory() = default;
  virtual double length_m(int type_index) const = 0;
  virtual Vehicle make(int type_index, Direction dir, int lane, double s_m, double speed_mps) = 0;
};

struct PlayInput {
  Step step = 0;
  double dt_s = 0.1;
  const EgoObservation& ego;
  const std::vector<ObservedVehicle>& world;  // sorted by id
  std::vector<bool>& available;               // per world index: free to cast (cleared as claimed)
  VehicleFactory& factory;
};

struct PlayOutput {
  std::optional<PlayReport> report;
  std::vector<ActorCommand> commands;
  struct Created {
    Vehicle vehicle;
    Region region;  // the outer region it is handed to meso in
  };
  std::vector<Created> created;
};

struct PlaySetting {
  DirectorConfig director;
  WindowConfig window;
  Lanes lanes;
  TypeTable types;
};

class PlayRun {
 public:
  PlayRun(const PlayConfig& play, const PlaySetting& setting);

  PlayOutput step(const PlayInput& in);
  PlayPhase phase() const { return phase_; }
  const PlayConfig& config() const { return play_; }
  // Vehicles this play holds (actors and cleared vehicles), so no other play casts them.
  std::vector<VehicleId> holds() const;
  // The vehicles playing its roles now (kNoVehicle for a role without one).
  std::vector<VehicleId> actors() const;

 private:
  struct Role {
    VehicleId actor = kNoVehicle;
    bool created = false;
    Step cast_step = 0;
    double command_mps = -1.0;  // the last desired speed given while transporting
    double position_error_m = 0.0;
    double speed_error_mps = 0.0;
    double hopeless_since_s = -1.0;  // since when its plan misses the start by far (< 0: it does not)
    double leaving_floor_mps = -1.0;  // leaving_ego_lane_floor_mps: its usual-speed part, fixed (< 0: none)
    double unplaced_since_s = -1.0;  // since when it has had no actor and no place to create one (< 0: not)
  };

  void prepare(const PlayInput& in, PlayOutput& out);
  // Per role, whether the ego's lane change has just mirrored the stage (stage.hpp, staged_beside)
  // and moved the start of the role, cast, to the ego's other side: casting then gives the role to
  // another vehicle where its actor would have to get past the ego (play_casting.cpp). Empty where
  // nothing was mirrored.
  std::vector<bool> restaged_roles(const PlayInput& in);
  // The ego's leader for the start-time estimate where it cannot get past it (stage.hpp,
  // unpassable_leader), at the speed it is expected to keep.
  std::optional<LeaderAhead> ego_leader(const PlayInput& in) const;
  // The ego drives well below its usual speed (kSlowedShare of its highest over the last
  // kUsualSpeedWindow_s, play.cpp) where no leader holds it: a driver who slowed down and holds the
  // lower speed for a while has the estimate put the start later than it will be once it speeds up
  // again, and no actor is judged hopeless on that estimate. (The bench's braking driver holds 60 %
  // of its speed for 6 s: in three stopped-vehicle runs, seeds 64, 94 and 97, the stopper, on its
  // way 250 m ahead, was given up 3 s into the hold for a vehicle behind the ego, two of them
  // created in the outer region behind, which ended 137-389 m short of the start.) Behind a leader
  // it cannot pass, the estimate drives it behind that leader (start_time.hpp): counted there as
  // well, the slowdown cost the slow truck play, whose ego slows behind the truck, 3 of 100 runs.
  bool ego_slowed_down(const PlayInput& in) const;
  // An actor ahead of the ego in the ego's lane whose start is in another lane (the ego's lane
  // change moved it in behind the actor) is asked no slower than the ego drives, nor than
  // kSlowedShare of the ego's usual speed when that began (whichever is lower), until it has left
  // that lane: it cannot fall back on the ego there, and slowing to do so while it waited for a
  // gap took the ego down with it (cut-in, stop 55: seed 37, both from 27 to 5 m/s in 70 s; seeds
  // 378 and 395 the same way). With the usual speed of the moment, the floor sank with the ego it
  // held at it (seed 37: 22 to 18 m/s in 30 s); with the usual speed alone, above an ego that had
  // slowed down, the cutter pulled away from it to 79 m ahead (seed 112). Below 0: no floor;
  // `role.leaving_floor_mps` is kept or reset. Such an actor is let in (let_in, play_clearing.cpp).
  double leaving_ego_lane_floor_mps(const PlayInput& in, const ObservedVehicle& actor, const Slot& slot, Role& role) const;
  // `actor` is ahead of the ego in the ego's lane and starts in another, `start_lane`.
  bool leaves_ego_lane_ahead(const PlayInput& in, const ObservedVehicle& actor, int start_lane) const;
  // Casts the roles without an actor, and the restaged ones whose actor would have to get past the
  // ego (`restaged`: restaged_roles); returns what it did ("" for nothing).
  std::string cast(const PlayInput& in, const std::vector<Slot>& slots, const Aim& aim, double time_to_start_s,
                   const std::vector<bool>& restaged, PlayOutput& out);
  // For a role that has had no actor and no place to create one for kRoomWait_s: takes off the
  // road the vehicle out of sight that keeps a place for `slot` from being free
  // (blocker_to_take_off), one at a time; returns what it did ("" for nothing).
  std::string make_room(const PlayInput& in, Role& role, const Slot& slot, double length_m,
                        const CastingSituation& at, const WindowBounds& window, PlayOutput& out);
  // Gives each actor the desired speed and lane that move it to its start (play_transport.cpp).
  void move_actors(const PlayInput& in, const std::vector<Slot>& slots, const Aim& aim, double time_to_start_s,
                   PlayOutput& out);
  void clear_zones(const PlayInput& in, const std::vector<Slot>& slots, const Aim& aim, double time_to_start_s,
                   PlayOutput& out);
  // Vehicles waiting to change into a lane they were asked for are let in (clearing.hpp,
  // follower_to_let_in); a vehicle that let one in drives on at its own speed in its lane.
  // `slots`: the roles' starts, `time_left_s` from now (an actor leaving the ego's lane for its
  // start's is let in too; one in place beside its start lets in the vehicle it swaps lanes with).
  void let_in(const PlayInput& in, const std::vector<Slot>& slots, double time_left_s, PlayOutput& out);
  // The lane `id` was asked to change into while it has not started moving there; -1 otherwise.
  int waiting_for_lane(const PlayInput& in, VehicleId id) const;
  // A vehicle that held back drives on as it likes, in its lane (an actor goes on its way:
  // move_actors).
  void stop_holding_back(const PlayInput& in, VehicleId id, PlayOutput& out);
  // Those holding back for a vehicle that no longer waits (it moved over, or left) drive on.
  void end_hold_backs_no_longer_needed(const PlayInput& in, PlayOutput& out);
  // Who may be let in: the cleared vehicles, and an actor leaving the ego's lane ahead of it.
  std::vector<VehicleId> waiting_to_be_let_in(const PlayInput& in, const std::vector<Slot>& slots) const;
  // Lets `v`, waiting to move into `lane`, in: picks the vehicle to hold back for it, if any may.
  void let_in_one(const PlayInput& in, const std::vector<Slot>& slots, double time_left_s, const ObservedVehicle& v,
                  int lane, PlayOutput& out);
  // Whether `follower`, holding back in `lane` at `hold_mps`, would hold up an actor on its way
  // to its start there (clearing.hpp, held_back_holds_up).
  bool holds_an_actor_up(const PlayInput& in, const std::vector<Slot>& slots, const ObservedVehicle& follower, int lane,
                         double hold_mps) const;
  // On one lane per direction, with a clear zone ahead of the ego in its lane: the vehicles behind
  // the ego in its lane, within the inner region, keep their lane (pass nobody) until the
  // handover. Nothing gets out from between the ego and an actor ahead of it there (casting.hpp,
  // stuck_between), and a follower that passed the ego during the preparation was caught there
  // by the oncoming traffic: 6 of the 13 failed slow truck runs with a truck cast at stop 35 (the
  // car 13-37 m ahead of the ego in the truck's clear zone at the start; seeds 17, 26, 60, 64, 77,
  // 94).
  void hold_followers(const PlayInput& in, PlayOutput& out);
  // On one lane per direction, with a clear zone ahead of the ego in its lane (the play as staged).
  bool zone_ahead_on_one_lane(const PlayInput& in) const;
  // Whether the play opens a gap in the oncoming traffic (DirectorConfig::oncoming_gap_m).
  bool opens_oncoming_gap(const PlayInput& in) const;
  // The gap: while the ego drives its first oncoming_gap_m from trigger point 1 and a role ahead
  // of it in its lane has no actor yet or another vehicle between the actor and the ego, not in
  // the middle of a pass (someone_between), every oncoming vehicle that no play holds, more than hidden_margin_m
  // beyond the inner region (out of the driver's sight, where vehicles are also created), is
  // withdrawn (taken off the road by its owner). The oncoming lane ahead then empties as the
  // oncoming vehicles in view drive by, and the vehicles between the ego and the actor can pass
  // it. Without it, cars between the ego and any truck it could be given stayed there
  // (casting.hpp, stuck_between): in most runs at 450 vehicles an hour each way the ego drives
  // in a platoon, and the play failed for want of a truck with nothing between (NOTES.md, stop
  // 39). Closed as soon as nobody is between but vehicles already passing: the ego uses the gap
  // too, and passed the truck in it or came early.
  void open_oncoming_gap(const PlayInput& in, PlayOutput& out);
  bool someone_between(const PlayInput& in) const;
  // A role whose start is ahead of the ego in the ego's lane (the truck).
  static bool ahead_in_ego_lane(const PlayRoleConfig& rc);
  // How far ahead of the ego the driver's sight ends for the director: hidden_margin_m beyond the
  // inner region, where it creates and takes off vehicles.
  double sight_edge_m() const { return setting_.window.inner_ahead_m + setting_.director.hidden_margin_m; }
  // Once the gap is closed (or was never needed) and the ego is behind every such actor with
  // nobody between, the oncoming lane is kept busy out of sight until the handover: where no
  // oncoming vehicle is within kFillSpacing_m of the driver's sight (hidden_margin_m beyond the
  // inner region), an autonomous one is created just beyond it, at the speed of the oncoming
  // traffic ahead (the play's scene: "dense oncoming traffic that prevents overtaking"). Not
  // while a vehicle of the ego's direction is passing behind the actor ahead, nor while the ego
  // passes. Without it the ego, right behind the truck, saw the empty lane the gap left behind
  // (some 25 s, until the generator's new arrivals at the window's edge had crossed the outer
  // region) or a natural gap, and passed the truck: a quarter of the failed runs (stop 42).
  void fill_oncoming_lane(const PlayInput& in, PlayOutput& out);
  // How far ahead of the ego the farthest role ahead of it in its lane has its actor, when every
  // such role has one in view ahead of the ego (inner region); -1 otherwise.
  double actors_ahead_in_view_m(const PlayInput& in) const;
  // A vehicle of the ego's direction passing (in the oncoming lane or moving there) between the
  // ego and just beyond the actor `actor_ahead_m` ahead of it. Not one behind the ego: a car
  // passing 200 m behind it kept the lane in front of the ego empty (slow truck, seed 36, stop 56;
  // counting only those ahead of the ego, 3 runs gained and none lost over seeds 1-600, stop 57).
  bool someone_passing_behind(const PlayInput& in, double actor_ahead_m) const;
  // An oncoming vehicle within kFillSpacing_m of the edge of the driver's sight `sight_m` ahead
  // of the ego (the vehicles this play created and not yet saw where they would be now).
  bool oncoming_near_sight(const PlayInput& in, double sight_m) const;
  // Whether a vehicle this play holds keeps the lane change it was asked for instead of `lane`
  // (clearing.hpp, keeps_lane_request).
  bool holds_lane_request(const ObservedVehicle& v, int lane, double now_s) const;
  // The vehicle `id` holds back for to let it in (let_in); kNoVehicle: none.
  VehicleId held_back_for(VehicleId id) const;
  bool holding_back(VehicleId id) const { return held_back_for(id) != kNoVehicle; }
  std::size_t role_of(VehicleId id) const;  // the role `id` plays; roles_.size(): none
  // Notes a lane change asked of `v` by `c` (one in its own lane ends a request).
  void note_lane_request(const ObservedVehicle& v, const ActorControl& c, double now_s);
  // What keeps the start condition from holding now ("" : nothing); sets the roles' errors.
  std::string start_problems(const PlayInput& in);
  // Hands over to the script, or fails with `problems` if there are any.
  void hand_over(const PlayInput& in, const std::string& problems, PlayOutput& out);
  void run(const PlayInput& in, PlayOutput& out);
  void release_all(const PlayInput& in, PlayOutput& out);
  void finish_release(const PlayInput& in, PlayOutput& out);

  // Sends `c` to `id` unless it was the last control sent to it. One command per vehicle per step:
  // a later phase of the step that commands a vehicle again replaces the earlier command (its
  // owner applies the last one anyway).
  void command(VehicleId id, const ActorControl& c, Step step, PlayOutput& out);
  ActorControl transported(double speed_mps, int lane) const;
  ActorControl releasing() const;
  ActorControl withdrawn() const;
  // A role to cast: without an actor, or with one that has missed its start by far for a while
  // (the ego changed lane, traffic held it up): it is replaced if a better one is found.
  bool open(const Role& r, const PlayInput& in) const;
  const ObservedVehicle* find(const PlayInput& in, VehicleId id) const;  // nullptr: not in the world, or kNoVehicle
  bool is_cleared(VehicleId id) const;  // asked by this play to leave a zone or keep its lane
  void report(const PlayInput& in, PlayOutput& out, std::string detail);
  double ego_progress(const EgoObservation& ego) const { return sign(ego.direction) * ego.s_m; }
  // The lane the play is staged beside (stage.hpp, staging_lane).
  int staged_lane(const PlayInput& in) const { return staging_lane(in.ego, setting_.lanes); }

  PlayConfig play_;
  PlayConfig staged_;  // play_ as staged beside the ego's lane (stage.hpp, staged_beside)
  std::optional<bool> mirrored_;  // whether staged_ is play_ mirrored (unset before the first preparation)
  PlaySetting setting_;
  PlayPhase phase_ = PlayPhase::kWaiting;
  StartTimeEstimator estimator_;
  RecentTop ego_usual_speed_;  // the ego's highest speed over kUsualSpeedWindow_s (play.cpp)
  std::vector<Role> roles_;
  std::map<VehicleId, ActorControl> sent_;  // the last control written to each vehicle held
  std::vector<VehicleId> cleared_;          // vehicles asked to leave a zone
  std::map<VehicleId, VehicleId> letting_in_;  // a vehicle let in -> the one holding back for it
  std::map<VehicleId, LaneRequest> lane_requests_;  // lane changes asked of cleared vehicles
  // Oncoming vehicles this play created to keep the lane busy (fill_oncoming_lane), until they
  // are seen in the world: where they were created, at what speed and when.
  struct Filler {
    VehicleId id = kNoVehicle;
    double s_m = 0.0;
    double speed_mps = 0.0;
    double time_s = 0.0;
  };
  std::vector<Filler> fillers_;
  // The vehicle taken off out of sight to make room for a creation (blocker_to_take_off), until it
  // is gone from the world: one at a time.
  VehicleId making_room_ = kNoVehicle;
  std::vector<ActorControl> scripted_;      // per role, once handed over
  std::optional<Script> script_;
  double estimated_start_s_ = -1.0;
  double reported_estimate_s_ = -1.0;
  double handover_time_s_ = -1.0;
  double trigger2_time_s_ = -1.0;  // when the ego passed trigger point 2 (< 0: not yet)
  std::string problems_at_trigger2_;  // what the start condition lacked on passing trigger point 2
  double release_until_s_ = -1.0;
  double last_cast_attempt_s_ = -1e9;
  double last_progress_report_s_ = -1e9;
  bool first_report_ = true;
  bool released_ = false;
  std::uint16_t created_count_ = 0;
};

}  // namespace entourage::director
