#pragma once
// The overtaking manoeuvre on a two-lane road with oncoming traffic, around the decision model of
// behaviour/overtaking.hpp: when to ask the four questions (every decision interval while held
// up, one draw per decision), which vehicles to pass (the leader and, when it drives in a tight
// platoon, up to a few vehicles ahead of it until a gap big enough to return into), the moves out
// and back as lateral movements between the own lane and the oncoming lane, the pass reviewed at
// every step, the return into any gap of the own lane that fits kinematically (a platoon's gaps
// included), and the abort: drop back towards the nearest gap that takes the overtaker and return
// as soon as the gap beside fits; an abort while still moving out pulls back in the way it came.
//
// Only drivers whose lane-change model is "overtaking", in the leftmost lane of their direction, on
// a road with oncoming traffic (DrivingEnvironment::two_way) overtake.

#include <cstdint>
#include <limits>

#include "traffic/driving_environment.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

// The vehicles ahead in the own lane that a pass would overtake.
struct PassChain {
  const Occupant* first = nullptr;  // the leader
  const Occupant* last = nullptr;   // the front-most vehicle to pass
  int count = 0;
  double gap_m = 0.0;                // from the overtaker's front to the first one's rear
  double length_m = 0.0;             // from the first one's rear to the last one's front
  double speed_mps = 0.0;            // the fastest of them
  double room_ahead_m = std::numeric_limits<double>::infinity();  // in front of the last one
};

PassChain pass_chain(const Vehicle& v, const LaneIndex& index, const OvertakingParams& p);

// The situation as the overtaking model sees it, for passing `chain` from the driver's position.
OvertakingSituation overtaking_situation(const Vehicle& v, const PassChain& chain, const LaneIndex& index,
                                         const DrivingEnvironment& env, double desired_speed_mps);

struct OvertakingStep {
  OvertakingState state;          // to commit
  bool lateral_start = false;     // a lateral movement starts now (lane_change holds it)
  LaneChangeState lane_change;
  double desired_speed_mps = 0.0; // the desired speed for this step (the passing speed in a pass)
  double accel_cap_mps2 = std::numeric_limits<double>::infinity();  // braking of an abort
  // The rest of the pass can be finished before the oncoming vehicle (the pass review's verdict,
  // with abort_margin_s): the overtaker does not brake for that vehicle, as the oncoming driver
  // does for it (the pass review, not the car-following model, decides whether to go on).
  bool clear_of_oncoming = false;
  std::uint64_t rng_state = 0;
  bool started = false;
  bool aborted = false;
};

// One step of the manoeuvre for `v`; `desired_speed_mps` is its desired speed at this place.
OvertakingStep overtaking_step(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env,
                               double desired_speed_mps);

// Lateral move back into the own lane: the gap beside it fits when neither the overtaker behind
// its new leader nor the new follower behind the overtaker has to brake harder than
// return_decel_mps2 (the follower is assumed to keep the overtaker's standstill gap); with an
// oncoming vehicle about to meet it, up to the overtaker's own braking limit, and for the follower
// up to follower_max_decel_mps2 as well (a truck behind brakes less hard than a car can).
bool can_return(const Vehicle& v, const LaneIndex& index, const DrivingEnvironment& env);

// Does this driver overtake in the oncoming lane here at all?
bool overtakes(const Vehicle& v, const DrivingEnvironment& env);

}  // namespace entourage
