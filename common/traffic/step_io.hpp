#pragma once
// What a region core (micro, meso) receives and produces in one step.
//
// Step k computes the state at time k*dt from the state at k-1: every vehicle's decision uses
// the world as published at k-1 (all owners and the ego), so all services see the same snapshot
// and a lockstep run is reproducible; the ego at k places the window for the step.

#include <optional>
#include <vector>

#include "core/ids.hpp"
#include "traffic/actor_control.hpp"
#include "traffic/handoff.hpp"
#include "traffic/vehicle.hpp"
#include "traffic/world.hpp"

namespace entourage {

struct StepInput {
  Step step = 0;                            // the step being computed
  EgoObservation ego;                       // the ego at `step`
  std::optional<EgoObservation> ego_prev;   // the ego at step - 1
  std::vector<ObservedVehicle> world_prev;  // every vehicle published for step - 1
  std::vector<Handoff> handoffs;            // handoffs received since the previous step
  std::vector<ActorCommand> commands;       // director commands written at step - 1, by vehicle id
};

// The ego at step - 1 as the traffic sees it: none at step 0, nor when the scenario's ego is
// transparent (a probe the traffic drives through: scenario `ego.transparent`).
inline const EgoObservation* ego_seen(const StepInput& in, bool ego_transparent) {
  return in.ego_prev && !ego_transparent ? &*in.ego_prev : nullptr;
}

// What a core publishes of a vehicle at a step: the world-state topic's fields (where it is, how
// it moves, what it looks like and signals), not its driver, which travels only in handoffs. A
// record of some 70 bytes instead of the vehicle's 480: every core copies one per owned vehicle
// at every step (services/meso/README.md, *Cost*).
struct VehicleReport {
  VehicleReport() = default;
  VehicleReport(const Vehicle& v, Region r)
      : id(v.id),
        region(r),
        type_index(v.type_index),
        direction(v.direction),
        indicator(v.indicator()),
        control(v.control.mode),
        lane(v.lane),
        target_lane(v.target_lane()),
        lateral_fraction(v.lane_change.lateral_fraction()),
        s_m(v.s_m),
        speed_mps(v.speed_mps),
        accel_mps2(v.accel_mps2),
        length_m(v.length_m),
        width_m(v.width_m),
        lane_change(v.lane_change),
        control_indicator(static_cast<Indicator>(v.control.indicator)) {}

  VehicleId id = 0;
  Region region = Region::kOutside;
  std::uint8_t type_index = 0;
  Direction direction = Direction::kForward;
  Indicator indicator = Indicator::kOff;
  ControlMode control = ControlMode::kAutonomous;
  int lane = 0;
  int target_lane = 0;            // the second lane it occupies while moving sideways (else `lane`)
  double lateral_fraction = 0.0;  // how far it has moved from `lane` towards `target_lane`, 0..1
  double s_m = 0.0;
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 4.5;
  double width_m = 1.8;
  // What carries the state forward by a step without its owner (traffic/carried_states.hpp): the
  // lane change under way (its phase, lanes, time into it and duration; the rest is the driver's
  // and travels in handoffs only) and what a controlled actor's indicator shows outside one.
  LaneChangeState lane_change;
  Indicator control_indicator = Indicator::kOff;
};

struct StepOutput {
  std::vector<VehicleReport> states;  // published for `step`, in id order
  std::vector<Handoff> handoffs;      // sent at `step`, in id order
};

}  // namespace entourage
