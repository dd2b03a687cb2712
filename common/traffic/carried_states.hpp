#pragma once
// Carrying a published vehicle state forward. Between two of meso's plans a vehicle's motion is
// fixed by its state: its speed, the acceleration of its ramp and its lane change under way
// (services/meso/README.md, *The model*). A reader that holds one state of it can therefore
// compute every later step exactly as meso moves it, with the same operations in the same order:
//
//   each step:  v' = v + a dt;   if v' <= 0: a = -v / dt   (it stops within the step, and stays)
//               v = max(0, v');  s = s + sign(direction) v dt
//               its lane change moves on by dt (continue_lane_change: a signal ends, a sideways
//               move goes on along its profile and ends in the target lane)
//
// A publisher then need not publish a vehicle whose state at a step is its previous one carried
// forward (SparseStates), and a reader rebuilds the publisher's every state from those it
// published and the vehicles it no longer has (StateTracks): bit for bit the states it would have
// published at every step.

#include <cstddef>
#include <vector>

#include "traffic/step_io.hpp"

namespace entourage {

// One step along a constant acceleration, stopped at standstill (MesoCore::move).
void advance_on_ramp(double& s_m, double& speed_mps, double& accel_mps2, Direction direction, double dt_s);

// A state one step later, had nothing set its ramp, its lane change or anything else anew.
VehicleReport carried_forward(const VehicleReport& r, double dt_s);

// The same state, field by field and bit for bit (the indicator and the region included).
bool same_state(const VehicleReport& a, const VehicleReport& b);

// The publisher's side: of a step's states, those a reader cannot carry forward from the ones
// published before. A vehicle is published at the step it first appears and whenever its state
// is not the previous step's carried forward (its ramp set at a plan, a lane change begun or
// called off, a command, a new region, a pass driven by micro's model at every step).
struct SparseStep {
  std::vector<VehicleReport> states;  // to publish, in id order
  std::vector<VehicleId> gone;        // vehicles of the step before that this step has not, in id order
};
class SparseStates {
 public:
  explicit SparseStates(double dt_s) : dt_s_(dt_s) {}
  // `states`: every state of the step, in id order.
  SparseStep select(const std::vector<VehicleReport>& states);

 private:
  double dt_s_;
  std::vector<VehicleReport> previous_;  // the step before's states, in id order
};

// The reader's side, for one publisher: its states at every step from those it published and the
// vehicles it no longer has (SparseStep).
class StateTracks {
 public:
  explicit StateTracks(double dt_s) : dt_s_(dt_s) {}
  // The next step: the last step's states without `gone`, carried forward, and `published` (in id
  // order) in place of those it replaces. Returns every state of the step, in id order.
  const std::vector<VehicleReport>& step(const std::vector<VehicleReport>& published, const std::vector<VehicleId>& gone);
  const std::vector<VehicleReport>& states() const { return states_; }

 private:
  double dt_s_;
  std::vector<VehicleReport> states_;  // the last step's, in id order
};

}  // namespace entourage
