#pragma once
// What the event director asks of a vehicle it has cast in a play (thesis ch. 3.1, paper IV).
// The vehicle stays with its owner (micro or meso) and keeps its own driver model; the control
// only changes what that driver aims for:
//   autonomous   everyday driving, nothing changed
//   transported  on its way to its start position: the desired speed is the director's (eased
//                down to at no more than the driver's comfortable deceleration), the only
//                lane change it makes is towards the director's lane (with the model's safety
//                test), and its acceleration rises no faster than max_jerk_mps3
//   controlled   the play runs: the speed goes to speed_mps at accel_mps2 (up) / decel_mps2
//                (down), never faster than car following behind its leader allows; a lane change
//                to `lane` starts at once and, if `force_lane`, without the model's safety test
//                (a scripted cut-in), only refused when the target lane is physically occupied
//   releasing    back to everyday driving: the driver's own model, acceleration rising no faster
//                than max_jerk_mps3
//   withdrawn    taken off the road by its owner where the driver cannot see it (beyond the
//                inner region; a gap the director opens in the oncoming traffic, director
//                README *A gap in the oncoming traffic*); where it can be seen, it drives on as
//                everyday traffic
// A control travels with the vehicle in every handoff, so an actor keeps its part across regions.

#include <cstdint>

#include "core/ids.hpp"

namespace entourage {

enum class ControlMode : std::uint8_t {
  kAutonomous = 0,
  kTransported = 1,
  kControlled = 2,
  kReleasing = 3,
  kWithdrawn = 4,
};

// A transported vehicle's desired speed that leaves the driver's own (a vehicle only asked to
// change or keep its lane: given its present speed instead, it would never speed up again).
inline constexpr double kOwnDesiredSpeed_mps = -1.0;

const char* to_string(ControlMode m);

struct ActorControl {
  ControlMode mode = ControlMode::kAutonomous;
  std::uint32_t play_id = 0;          // the play it acts in (meaningful unless autonomous)
  double speed_mps = 0.0;             // transported: desired speed (kOwnDesiredSpeed: the driver's
                                      // own); controlled: target speed
  double accel_mps2 = 1.0;            // controlled: rate of speeding up towards speed_mps (> 0)
  double decel_mps2 = 1.0;            // controlled: rate of slowing down towards speed_mps (> 0)
  double max_jerk_mps3 = 2.0;         // transported, releasing: limit on the rise of acceleration
  int lane = -1;                      // a lane to reach in its own direction, -1: none
  bool force_lane = false;            // controlled: change lane without the safety test
  double lane_change_duration_s = 0;  // controlled: lateral movement time, 0: the driver's own
  std::uint8_t indicator = 0;         // controlled: 0 off, 1 left, 2 right (besides lane changes)

  bool active() const { return mode != ControlMode::kAutonomous; }
};

bool operator==(const ActorControl& a, const ActorControl& b);
inline bool operator!=(const ActorControl& a, const ActorControl& b) { return !(a == b); }

// A control addressed to one vehicle, written by the director at one step and applied by the
// vehicle's owner at the next step boundary (like a handoff).
struct ActorCommand {
  VehicleId vehicle = 0;
  Step step = 0;  // the step at which the director wrote it
  ActorControl control;
};

}  // namespace entourage
