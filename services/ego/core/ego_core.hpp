#pragma once
// The ego stand-in: drives the ego along the road in place of a person in a simulator, so that
// Entourage can run alone. Two drivers (scenario `ego`):
//   idm            an IDM driver at a desired speed, changing lanes with MOBIL if enabled;
//   speed_profile  a target speed over road position, followed with a bounded acceleration, with
//                  IDM's interaction term keeping a safe gap to a leader.
// It uses the same driving functions as the simulated vehicles (common/traffic/driving.hpp),
// slows for curves and lower limits like them (its desired speed is its basic one; no overtaking),
// and sees the world as published at the previous step.

#include <vector>

#include "road/road.hpp"
#include "scenario/config.hpp"
#include "traffic/driving.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"
#include "traffic/world.hpp"

namespace entourage::ego {

// The stand-in's driver as the scenario's ego block describes it (its desired speed the basic one:
// a speed profile is applied by the core). Also used to put drivers like it into a whole road of
// traffic (entourage-bench-catchups).
DriverParams ego_driver(const EgoConfig& e, const DrivingEnvironment& env, std::uint64_t seed);

class EgoCore {
 public:
  // `seed` seeds the stand-in driver's own decisions (its overtakings); default the scenario's.
  explicit EgoCore(const ScenarioConfig& scenario);
  EgoCore(const ScenarioConfig& scenario, std::uint64_t seed);

  // The ego at step 0.
  EgoObservation initial() const { return observe(0); }
  // Advances from the previous step to `step`, seeing `world_prev` (the vehicles at step - 1).
  EgoObservation step(Step step, const std::vector<ObservedVehicle>& world_prev);

  // Past the end of the road (with room for the window ahead): a run must stop here.
  bool at_road_end() const;
  const Vehicle& vehicle() const { return self_; }

 private:
  EgoObservation observe(Step step) const;
  // Is the driver in one of its scenario stops at time t_s (braking for it, or standing)?
  bool stopping(double t_s);
  double profile_speed_mps(double s_m) const;

  ScenarioConfig scenario_;
  Road road_;
  DrivingEnvironment env_;
  Vehicle self_;
  LaneIndex index_;
  std::size_t next_stop_ = 0;           // the scenario stop to come or under way
  double standing_since_s_ = -1.0;      // when the current stop came to a standstill (-1: not yet)
};

}  // namespace entourage::ego
