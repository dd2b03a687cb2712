#pragma once
// One driver's decisions in a step, from its own state and what it sees (the lane index built
// from the world state at the previous step): its acceleration (car following, emergency braking)
// and its lane change (MOBIL decision, indicator, lateral movement over time). Pure functions:
// the caller computes every driver's decision from the same snapshot, then commits them all.

#include <optional>

#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

// Timing of lane changes (thesis ch. 3.2: lane changes must take time to look real).
struct DrivingRules {
  double signal_s = 1.5;           // indicator on before the lateral movement starts
  double max_signal_wait_s = 4.0;  // a change that has not become safe by then is given up
  double min_interval_s = 5.0;     // from the end of one change to the decision on the next
};

struct Decision {
  double accel_mps2 = 0.0;
  LaneChangeState lane_change;  // the state to commit
  bool emergency = false;       // the emergency regime overrode the model
};

// The leader of `v` in `lane` (nullptr on a free road).
const Occupant* leader_of(const Vehicle& v, const LaneIndex& index, int lane);

// Car-following acceleration of `v` behind `leader`, with the emergency regime: when the model
// would not stop the vehicle in time behind a slower leader, brake as needed, up to the limit.
double accel_behind(const Vehicle& v, const Occupant* leader, bool* emergency = nullptr);

// MOBIL evaluation of a change from v.lane to `target` (no checks of timing or lane range).
struct LaneChangeOption {
  int target_lane = 0;
  bool safe = false;
  double advantage_mps2 = 0.0;
};
LaneChangeOption evaluate_lane_change(const Vehicle& v, const LaneIndex& index, int target);

// The full decision of one driver for this step.
Decision decide(const Vehicle& v, const LaneIndex& index, const DrivingRules& rules, double dt_s);

// Moves `v` over one step with constant acceleration (ballistic update; a vehicle that would
// roll backwards stops instead) and advances its lane change. Commits `d` first.
void commit(Vehicle& v, const Decision& d, double dt_s);

// For models that decide no lane changes (meso, the generator's front zone): a vehicle handed over
// in the middle of a lane change finishes the lateral movement, one that only signalled drops it.
void continue_lane_change(Vehicle& v, double dt_s);

// The nearer of the leaders in the lanes `v` occupies (both while it changes lane).
const Occupant* nearest_leader(const Vehicle& v, const LaneIndex& index);

}  // namespace entourage
