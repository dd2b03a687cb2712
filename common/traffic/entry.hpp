#pragma once
// Where a new vehicle can enter a lane: the room it needs ahead and leaves behind. Shared by the
// generator (window edges, initial fill) and the road simulation (sources).

#include <cstdint>
#include <limits>
#include <optional>

#include "behaviour/idm.hpp"
#include "scenario/config.hpp"
#include "traffic/lane_index.hpp"

namespace entourage {

// The IDM parameters of a type's mean driver.
IdmParams mean_idm(const VehicleTypeConfig& type);

// The gap a driver wants behind a leader: IDM's s*(v, v - v_leader) with the driver's parameters,
// and never less than s0 plus half the time gap (where s* shrinks to s0 behind a leader pulling
// away). A vehicle entering with less would brake at once.
double wanted_gap_m(const IdmParams& driver, double speed_mps, double leader_speed_mps);

// What a vehicle does when it would be closer to the leader in a lane than it wants: it takes the
// leader's speed (it has caught up with it on the way: sources, the rear edge), or it waits for
// room at its own speed (the front edge, where room opens at the sum of both speeds).
enum class EntryPolicy : std::uint8_t { kMatchLeader, kOwnSpeed };

struct EntrySpot {
  int lane = 0;
  double speed_mps = 0.0;  // the speed it can enter with (its own, or its leader's if held up)
};

// The lane where a vehicle of `type` driven by `driver` can enter at progress `progress_m` of
// `dir`, preferring the lane that lets it drive fastest (then the rightmost); nullopt if no lane
// has room. A lane that a vehicle of the other direction uses ahead (an overtaker) has no room. `preferred` (if valid) wins ties. The follower there is judged with the same
// parameters (its own are not in the index).
std::optional<EntrySpot> find_entry(const LaneIndex& index, Direction dir, double progress_m, double speed_mps,
                                    const VehicleTypeConfig& type, const IdmParams& driver, int preferred_lane = -1,
                                    EntryPolicy policy = EntryPolicy::kMatchLeader);

}  // namespace entourage
