#pragma once
// One driver's decisions in a step, from its own state, what it sees (the lane index built from
// the world state at the previous step) and the road (driving_environment.hpp): its acceleration
// (car following with the desired speed of the place, the Human Driver Model's delay and errors,
// obstacles, the emergency regime) and its lane change (MOBIL, mandatory changes, overtaking in
// the oncoming lane). Pure functions: the caller computes every driver's decision from the same
// snapshot, then commits them all.

#include <cstdint>

#include "traffic/driving_environment.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

struct Decision {
  double accel_mps2 = 0.0;
  LaneChangeState lane_change;   // the state to commit
  OvertakingState overtaking;    // the state to commit
  double hdm_decided_mps2 = 0.0; // the HDM's undelayed decision, remembered for the reaction time
  std::uint64_t rng_state = 0;   // the driver's random stream after this step's draws
  bool emergency = false;        // the emergency regime overrode the model
  bool mandatory_change = false; // the lane change started is a mandatory one
};

// The driver's car-following parameters at its place: its own, with the desired speed that speed
// adaptation gives there (and the passing speed while it overtakes).
CarFollowingParams local_params(const Vehicle& v, const DrivingEnvironment& env);

// The leader of `v` in `lane` (nullptr on a free road).
const Occupant* leader_of(const Vehicle& v, const LaneIndex& index, int lane);

// Car-following acceleration of `v` behind `leader` with parameters `cf`, with the emergency
// regime: when the model would not stop the vehicle in time behind a slower leader, brake as
// needed, up to the vehicle's limit.
double accel_behind(const Vehicle& v, const CarFollowingParams& cf, const Occupant* leader, bool* emergency = nullptr);
// The same with the driver's own (basic) parameters.
double accel_behind(const Vehicle& v, const Occupant* leader, bool* emergency = nullptr);

// The deceleration that stops the approach to something `gap_m` ahead, closing at `closing_mps`,
// before the gap closes (0 if not closing).
double stopping_decel_mps2(double gap_m, double closing_mps);

// An overtaker of the other direction in v's own lane that is already moving back into its own
// lane (or calling its pass off) and will be out of v's lane before they meet, `gap_m` ahead at
// `closing_mps`: no obstacle. (Braked for, a car at 28 m/s braked at 9 m/s^2 for one 230 m ahead
// that was a second from the end of its return: rural_ego_slow, seed 1, stop 26.)
bool out_of_the_way_before_meeting(const Vehicle& v, const Occupant& oncoming, int lane, double gap_m,
                                   double closing_mps, const DrivingEnvironment& env);

// The deceleration that keeps `min_gap_m` to a leader `gap_m` ahead when closing in on it at
// `closing_mps`, both at constant speed (0 if not closing); infinite inside the standstill gap.
double keep_gap_decel_mps2(double gap_m, double min_gap_m, double closing_mps);
// The same behind a leader braking at `leader_brake_mps2` (0: holding its speed): also a stop behind
// where the leader stops (Kesting, Treiber & Helbing's heuristic with the leader keeping its
// deceleration).
double keep_gap_behind_braking_mps2(double gap_m, double min_gap_m, double follower_mps, double leader_mps,
                                    double leader_brake_mps2);

// The full decision of one driver for this step.
Decision decide(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env);

// Moves `v` over one step with constant acceleration (ballistic update; a vehicle that would
// roll backwards stops instead), advances its lane change, its overtaking and the HDM's state.
// Commits `d` first.
void commit(Vehicle& v, const Decision& d, double dt_s);

// For models that decide no lane changes (meso, the generator's front zone): a vehicle handed over
// in the middle of a lane change finishes the lateral movement, one that only signalled drops it.
void continue_lane_change(Vehicle& v, double dt_s);
// The same on the lane change and the lane alone (a published state carried forward,
// traffic/carried_states.hpp).
void continue_lane_change(LaneChangeState& lc, int& lane, double dt_s);

// The nearer of the leaders in the lanes `v` occupies (both while it changes lane).
const Occupant* nearest_leader(const Vehicle& v, const LaneIndex& index);

}  // namespace entourage
