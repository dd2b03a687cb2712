#pragma once
// Where a new vehicle can enter a lane: the room it needs ahead and leaves behind. Shared by the
// generator (window edges, initial fill) and the road simulation (sources).

#include <limits>
#include <optional>

#include "scenario/config.hpp"
#include "traffic/lane_index.hpp"

namespace entourage {

// The gap a driver of `type` wants behind a leader: IDM's s*(v, v - v_leader) with the type's
// mean parameters, and never less than s0 plus half the time gap (where s* shrinks to s0 behind a
// leader pulling away).
double wanted_gap_m(const VehicleTypeConfig& type, double speed_mps, double leader_speed_mps);

struct EntrySpot {
  int lane = 0;
  double speed_mps = 0.0;  // the speed it can enter with (its own, or its leader's if held up)
};

// The lane where a vehicle of `type` can enter at progress `progress_m` of `dir`, preferring the
// lane that lets it drive fastest (then the rightmost); nullopt if no lane has room. `preferred`
// (if valid) wins ties.
std::optional<EntrySpot> find_entry(const LaneIndex& index, Direction dir, double progress_m, double speed_mps,
                                    const VehicleTypeConfig& type, int preferred_lane = -1);

}  // namespace entourage
