#pragma once
// The outer regions: a cheaper, mesoscopic simulation of the vehicles between the inner region
// and the window's edges (thesis ch. 3.2, paper II). One process may serve both outer regions or
// only the front or the rear one. Phases of a step:
//   adopt     handoffs addressed to this meso instance join the fleet; director commands reach
//             their actors
//   perceive  the lane index from the fleet, the rest of the world at step-1 and the ego (only
//             at a step that plans)
//   plan      every vehicle once per update period (`update_period_s`), and an alert one (its
//             leader brakes hard, an oncoming vehicle ahead, an emergency) at every step, all
//             from the same snapshot, then committed: its speed ramp over the next period from its gap and its
//             desired speed at its place (meso_model.hpp), and its lane choice (meso_lanes.hpp).
//             Between plans a vehicle keeps its ramp (one that just joined, the acceleration it
//             came with) and only a lane change just begun is checked, against the vehicles that
//             just joined
//   move      every vehicle along its ramp and its lane change, one step
//   hand off  vehicles in the inner region go to micro, vehicles in a region this instance does
//             not serve go to the meso that does, vehicles of the ego's direction beyond the front
//             edge go on in the generator's front zone, other vehicles beyond the edges retire

#include <cstdint>
#include <optional>
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
#include "traffic/unseen_oncoming.hpp"

namespace entourage::meso {

struct Counters {
  std::uint64_t adopted = 0;
  std::uint64_t to_micro = 0;
  std::uint64_t to_other_meso = 0;
  std::uint64_t retired = 0;
  std::uint64_t taken_off = 0;  // withdrawn by the director out of the driver's sight (retired)
  std::uint64_t to_front_zone = 0;  // left ahead in the ego's direction: on to the generator
  std::uint64_t duplicate_handoffs = 0;
  std::uint64_t commands_applied = 0;  // director commands to vehicles owned here
  std::uint64_t emergency_stops = 0;  // plans where the floor-gap guard overrode braking
  std::uint64_t mandatory_lane_changes = 0;
  std::uint64_t called_off_lane_changes = 0;  // changes just begun whose target lane filled up (meso_lanes.hpp)
  std::uint64_t steps = 0;
  std::uint64_t planning_steps = 0;  // steps that built the lane index and planned every vehicle
  std::uint64_t plans = 0;           // vehicle plans (speed ramp and lane choice) made
  std::uint64_t alert_plans = 0;     // of which between updates, for alert vehicles
  std::uint64_t overtakings_started = 0;  // passes in the oncoming lane begun in the outer regions
  std::uint64_t overtaking_steps = 0;     // steps with a pass under way here (micro's model drives it)
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
  // What becomes of a vehicle at the end of a step.
  enum class Fate : std::uint8_t { kStays, kToFrontZone, kRetires, kTakenOff, kToMicro, kToOtherMeso };

  void adopt(const StepInput& in);
  // Between two plans: a lane change just begun is called off when a vehicle that has just joined
  // took its room (meso_lanes.hpp, crowds_change).
  void confirm_changes();
  void perceive(const StepInput& in);
  // Plans every vehicle (`everyone`, once per update period) or only the alert ones (in between),
  // each over the `steps_left` steps to the next update. A vehicle is alert, and planned at every
  // step, while its leader brakes harder than it would brake comfortably, an oncoming vehicle is
  // its obstacle, or its plan had to keep it off its leader (an emergency): where a second
  // without a look would be too long.
  void plan(bool everyone, int steps_left);
  bool alert(VehicleId id) const;
  static bool calls_for_alert(const Vehicle& v, const Ahead& ahead, const MesoSpeed& plan);
  // Overtaking in the oncoming lane of a two-lane road: a driver that overtakes asks at each plan
  // whether to start (as micro's drivers do once a decision interval); from the start until it is
  // back in its lane it is driven by micro's driver model at every step.
  bool overtaking(const Vehicle& v) const;
  bool starts_overtaking(Vehicle& v, double desired_speed_mps);
  void drive_overtakers();
  void move();
  // `r`: the region it is in (w.region_of).
  Fate fate_of(const Vehicle& v, Region r, const WindowBounds& w) const;
  // The nearer leader of the lanes it occupies (of its own lane only if `own_lane_only`: a change
  // called off), an oncoming vehicle in its lane, or the start of a closure of its lane.
  Ahead ahead_of(const Vehicle& v, bool own_lane_only) const;
  const EquilibriumSpeed& equilibrium_of(const Vehicle& v);
  // The equilibrium it is planned by at `desired_speed_mps`: its driver's own (equilibrium_of), or,
  // asked to drive faster than its driver wishes (by the director, or a section that raises the
  // drivers' speeds), its model's at that speed, as micro's model drives it (the
  // own relation is capped at the driver's desired speed within a kilometre of any leader: an
  // actor asked to speed up in meso did not, cut-in seed 136, a cutter asked to 36.8 m/s drove on
  // at its own 30.9 for a minute, 270 m behind its start at the handover).
  // The raised relation is made in `raised` (the caller's, for the one plan), two entries of it computed.
  const EquilibriumSpeed& equilibrium_at(const Vehicle& v, double desired_speed_mps,
                                         std::optional<EquilibriumSpeed>& raised);
  StepOutput hand_off(const StepInput& in);
  bool serves(Region r) const;

  ScenarioConfig scenario_;
  ServiceId self_;
  std::vector<Region> regions_;
  bool serves_rear_;   // regions_ as looked up at every step
  bool serves_front_;
  HandoffInbox inbox_;
  Fleet fleet_;
  LaneIndex index_;
  LaneRules lane_rules_;
  MesoModelParams model_;
  int steps_per_plan_ = 1;              // the update period in steps
  std::vector<VehicleId> newcomers_;    // joined at this step
  std::vector<std::size_t> overtakers_;  // fleet positions driven by micro's model at this step, ascending
  std::vector<VehicleId> alert_;         // planned at every step (plan), in id order
  DrivingEnvironment env_;
  UnseenOncoming unseen_;  // the oncoming traffic beyond the window's front edge (traffic/unseen_oncoming.hpp)
  std::unordered_map<VehicleId, EquilibriumSpeed> equilibrium_;  // per owned vehicle's driver
  Counters counters_;
};

}  // namespace entourage::meso
