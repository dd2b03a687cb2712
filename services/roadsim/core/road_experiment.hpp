#pragma once
// The road simulation as an experiment (entourage-roadsim, the fundamental-diagram and SUMO
// benchmarks): a scenario's vehicle types and demand with a chosen model, on a whole road without a
// moving window (traffic/road_sim.hpp), observed by loop detectors. Pure: the caller times it.

#include <cstdint>
#include <string>
#include <vector>

#include "scenario/config.hpp"
#include "traffic/detector_stats.hpp"
#include "traffic/road_sim.hpp"

namespace entourage::roadsim {

struct ExperimentConfig {
  // Overrides of every vehicle type's driver ("" / -1: the scenario's own).
  std::string car_following;        // idm, modified_idm, gipps
  int human_driver = -1;            // 0 off, 1 on (with the type's HDM parameters or the defaults)
  std::string lane_change;          // mobil, none, overtaking
  double forward_flow_veh_per_h = -1.0;
  double backward_flow_veh_per_h = -1.0;
  int lanes = -1;                   // lanes per direction
  double decision_interval_s = -1.0; // MOBIL decision interval (DrivingRules; -1: its default)
  // The road: the scenario's own, or a straight road of length_m at the scenario's base limit.
  bool scenario_road = false;
  double length_m = 8000.0;
  double duration_s = 1800.0;
  double warmup_s = 300.0;          // detectors and mean speed start after this
  double interval_s = 60.0;         // detector aggregation
  std::vector<double> detectors_m;  // default: 3/4 along each simulated direction
  std::uint64_t seed = 1;
};

// The scenario with the overrides applied, or an error naming the bad value.
struct Prepared {
  ScenarioConfig scenario;
  RoadSimConfig road;
  std::string error;
  bool ok() const { return error.empty(); }
};
Prepared prepare(const ScenarioConfig& scenario, const ExperimentConfig& config);

struct ExperimentResult {
  std::vector<DetectorInterval> intervals;  // every detector, both directions simulated
  RoadSimCounters counters;
  std::uint64_t vehicle_updates = 0;        // over the whole run, warm-up included
  std::uint64_t steps = 0;
  double mean_speed_mps = 0.0;              // space mean over all vehicle-steps after the warm-up
  double mean_trip_speed_mps = 0.0;         // mean over trips of road length / travel time (all trips)
  std::size_t max_queue = 0;                // vehicles waiting at an entrance, at most
};

// Runs a prepared experiment to the end. `progress` (may be null) is called every simulated minute.
ExperimentResult run_experiment(const Prepared& prepared, const ExperimentConfig& config,
                                void (*progress)(double time_s, const RoadSim& sim) = nullptr);

// The detector intervals with the largest flow sustained over `window` consecutive intervals
// (a capacity estimate at that detector): the mean flow of the best window, per lane.
double max_sustained_flow_per_lane(const std::vector<DetectorInterval>& intervals, Direction dir, double detector_m,
                                   int window);

}  // namespace entourage::roadsim
