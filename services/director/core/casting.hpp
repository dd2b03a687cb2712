#pragma once
// Casting (paper IV): which vehicle plays which role. A vehicle's cost for a role is how much it
// must change its driving to be at the role's start in time: the change from its present speed
// to the average speed that brings it there, plus a lane-change cost for each lane to change and
// each vehicle to get past. A vehicle that must get past the ego to a slot in the ego's lane costs
// a creation more on top: it needs the ego's speed to be left behind and a gap ahead of the ego to
// come back in, neither of which the director controls (a lead cast behind the ego sat there for
// the whole preparation). It cannot play the role when that average speed lies outside the
// transport band (stage.hpp) or it would have to get past the ego where actors cannot (one lane
// per direction: actors do not overtake), nor there with a vehicle between it and the ego that
// would stand in a clear zone at the start (stuck_between). Roles are then assigned jointly
// (assignment.hpp); a role without a fitting vehicle gets a new one, created where the driver
// cannot see it.

#include <cstdint>
#include <optional>
#include <vector>

#include "director/core/stage.hpp"
#include "director/core/zones.hpp"

namespace entourage::director {

struct CastingSituation {
  const std::vector<ObservedVehicle>& world;
  const EgoObservation& ego;
  double time_to_start_s = 0.0;     // until the aim (stage.hpp: the start, or a short horizon)
  double ego_s_at_handover_m = 0.0; // where the ego is then
  Lanes lanes;
  TypeTable types;
  std::vector<ZoneAtStart> zones = {};  // the play's clear zones at the start (the ego then)
  bool oncoming_gap = false;  // the play opens a gap in the oncoming traffic (play.hpp, open_oncoming_gap)
};

// On one lane per direction nothing gets out from between the ego and a vehicle ahead of it (actors
// do not overtake, the others only where the oncoming lane lets them): a vehicle between them now
// is still between them at the start. Where a clear zone of the slot's lane lies between the ego
// and a slot ahead of it then, a vehicle at `s_m` with any other vehicle between it and the ego
// cannot play the role (the play would fail on that vehicle in the zone). Unless the play opens a
// gap in the oncoming traffic (`at.oncoming_gap`), in which the vehicles between may pass it: then
// only a vehicle whose driver never overtakes (a truck) is stuck there. (A truck created out of
// sight beyond two trucks of the traffic was cast before one of them that needed the right speed,
// and the play failed on them, or on the ego passing the whole queue in the gap: slow truck, seed
// 27, stop 43.)
bool stuck_between(const Slot& slot, double s_m, VehicleId self, const CastingSituation& at);

// Whether `v` must get past the ego into the ego's lane to reach `slot` (a cutter left behind the
// ego when the ego changed lanes and the play was mirrored: stage.hpp, staged_beside). Casting
// counts it as costly as a creation (casting_cost).
bool passes_ego_to(const Slot& slot, const ObservedVehicle& v, const CastingSituation& at);

// The cost of `v` playing a role with start `slot` (infinite: it cannot).
double casting_cost(const Slot& slot, const PlayRoleConfig& role, const ObservedVehicle& v, const CastingSituation& at,
                    const DirectorConfig& cfg);

// Which vehicle of `world` plays each role (roles[r] starting at slots[r]): per role the index into
// world, or -1 (create one). `available[i]`: world[i] may be cast (not an actor already). A role is
// left to a creation where every vehicle costs more than creating one (creation_cost_for).
std::vector<int> cast_roles(const std::vector<Slot>& slots, const std::vector<PlayRoleConfig>& roles,
                            const std::vector<bool>& available, const CastingSituation& at, const DirectorConfig& cfg);
// The same with a situation of its own for each role (the same world and ego): the time and the
// ego's place where the role's way leads first (way_to, stage.hpp), and what a creation would cost
// for each role (`creation_costs`; empty: a creation's flat cost for every role).
std::vector<int> cast_roles(const std::vector<Slot>& slots, const std::vector<PlayRoleConfig>& roles,
                            const std::vector<bool>& available, const std::vector<CastingSituation>& at_role,
                            const DirectorConfig& cfg, const std::vector<double>& creation_costs = {});

// The index in the world of the available vehicle, other than those in `taken` (world indices, -1:
// none), that plays the role at the lowest finite cost; -1 if none can. For a role that cast_roles
// left to a creation where no vehicle can be created (hidden_placement finds no place).
int cheapest_fit(const Slot& slot, const PlayRoleConfig& role, const std::vector<bool>& available,
                 const CastingSituation& at, const std::vector<int>& taken, const DirectorConfig& cfg);

// Where to create a vehicle of length `length_m` for `slot`: out of sight (an outer region, at
// least hidden_margin_m beyond the inner region), from where it reaches the slot in time at a
// speed inside the transport band, with a safe gap to its neighbours in the slot's lane.
struct Placement {
  double s_m = 0.0;
  double speed_mps = 0.0;
  Region region = Region::kOutside;
  bool passes_ego = false;  // behind the ego, for a start ahead of it in its lane
};
std::optional<Placement> hidden_placement(const Slot& slot, double length_m, const CastingSituation& at,
                                          const WindowBounds& window, const DirectorConfig& cfg);

// Where hidden_placement finds no free place on one lane per direction and no vehicle of the
// traffic can play the role (cheapest_fit), the vehicle to take off the road to make one: of the
// places hidden_placement tries, one that a single vehicle keeps from being free, that vehicle
// available and out of sight itself (where the window's edges take vehicles off as well); the
// world index of the vehicle for the place nearest the slot's speed, -1 if none. (A column of cars
// at 23 m/s in the outer region ahead, 50-70 m apart, left no room for a truck and 1.5 s on either
// side: the slow truck had no truck at all, seed 22, stop 56.)
int blocker_to_take_off(const Slot& slot, double length_m, const std::vector<bool>& available,
                        const CastingSituation& at, const WindowBounds& window, const DirectorConfig& cfg);

// What leaving a role to a creation at `place` costs, in casting_cost's units: a creation's flat
// cost, and where the place is behind the ego for a start ahead of it in the ego's lane, that cost
// again, as for a vehicle of the traffic that must get past the ego (casting_cost). With no place
// (none free now; one is usually found a moment later) the flat cost. Priced flat, a lead vehicle
// created 250 m behind the ego was preferred to a car 94 m ahead of it in its lane that had five
// slower vehicles to get past, and the ego, speeding up from 17 to 33 m/s, left it 125 m short
// (lead vehicle, seed 126, stop 53).
double creation_cost_for(const std::optional<Placement>& place, const DirectorConfig& cfg);

}  // namespace entourage::director
