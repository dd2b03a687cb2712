#pragma once
// The outer regions: a cheaper, mesoscopic simulation of the vehicles between the inner region
// and the window's edges (thesis ch. 3.2, paper II). One process may serve both outer regions or
// only the front or the rear one. Phases of a step:
//   adopt     handoffs addressed to this meso instance join the fleet; director commands reach
//             their actors
//   perceive  the lane index from the fleet, the rest of the world at step-1 and the ego
//   move      every vehicle's next speed from its gap and its desired speed at its place
//             (meso_model.hpp) and lane choice (meso_lanes.hpp) from the same snapshot, then
//             integrate
//   hand off  vehicles in the inner region go to micro, vehicles in a region this instance does
//             not serve go to the meso that does, vehicles of the ego's direction beyond the front
//             edge go on in the generator's front zone, other vehicles beyond the edges retire

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "meso/core/meso_lanes.hpp"
#include "meso/core/meso_model.hpp"
#include "road/window.hpp"
#include "scenario/config.hpp"
#include "traffic/driving_environment.hpp"
#include "traffic/fleet.hpp"
#include "traffic/handoff.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/step_io.hpp"

namespace entourage::meso {

struct Counters {
  std::uint64_t adopted = 0;
  std::uint64_t to_micro = 0;
  std::uint64_t to_other_meso = 0;
  std::uint64_t retired = 0;
  std::uint64_t to_front_zone = 0;  // left ahead in the ego's direction: on to the generator
  std::uint64_t duplicate_handoffs = 0;
  std::uint64_t commands_applied = 0;  // director commands to vehicles owned here
  std::uint64_t emergency_stops = 0;  // vehicle-steps where the floor-gap guard overrode braking
  std::uint64_t mandatory_lane_changes = 0;
  std::uint64_t called_off_lane_changes = 0;  // changes just begun whose target lane filled up (meso_lanes.hpp)
};

// The outer regions served by a meso instance (kMesoBoth, kMesoFront or kMesoRear).
std::vector<Region> regions_of_instance(std::uint8_t instance);

// The meso model's parameters for a scenario: leaders brake at most as hard as the hardest-braking
// vehicle type, and never harder than the friction limit's default.
MesoModelParams model_params_for(const ScenarioConfig& scenario);

class MesoCore {
 public:
  MesoCore(const ScenarioConfig& scenario, ServiceId self);

  StepOutput step(const StepInput& in);

  const Fleet& fleet() const { return fleet_; }
  const Counters& counters() const { return counters_; }

 private:
  void adopt(const StepInput& in);
  void perceive(const StepInput& in);
  void move();
  // The nearer leader of the lanes it occupies (of its own lane only if `own_lane_only`: a change
  // called off), an oncoming vehicle in its lane, or the start of a closure of its lane.
  Ahead ahead_of(const Vehicle& v, bool own_lane_only) const;
  const EquilibriumSpeed& equilibrium_of(const Vehicle& v);
  StepOutput hand_off(const StepInput& in);
  bool serves(Region r) const;

  ScenarioConfig scenario_;
  ServiceId self_;
  std::vector<Region> regions_;
  HandoffInbox inbox_;
  Fleet fleet_;
  LaneIndex index_;
  LaneRules lane_rules_;
  MesoModelParams model_;
  DrivingEnvironment env_;
  std::unordered_map<VehicleId, EquilibriumSpeed> equilibrium_;  // per owned vehicle's driver
  Counters counters_;
};

}  // namespace entourage::meso
