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

struct VehicleReport {
  Vehicle vehicle;
  Region region = Region::kOutside;
};

struct StepOutput {
  std::vector<VehicleReport> states;  // published for `step`, in id order
  std::vector<Handoff> handoffs;      // sent at `step`, in id order
};

}  // namespace entourage
