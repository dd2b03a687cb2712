#pragma once
// Loop-detector statistics from the crossings a road simulation records (road_sim.hpp): per
// interval the flow, the time-mean speed (arithmetic mean of spot speeds) and the space-mean
// speed (their harmonic mean), and the density k = q / v_s (Wardrop's relation for a stationary
// interval; ../shared/notes/traffic-theory.md). Values are for the whole cross-section of one
// direction and per lane.

#include <vector>

#include "traffic/road_sim.hpp"

namespace entourage {

struct DetectorInterval {
  double start_s = 0.0;
  double end_s = 0.0;
  double detector_m = 0.0;
  Direction direction = Direction::kForward;
  int lanes = 1;
  std::size_t vehicles = 0;
  double flow_veh_per_h = 0.0;           // all lanes
  double time_mean_speed_mps = 0.0;
  double space_mean_speed_mps = 0.0;
  double density_veh_per_km = 0.0;       // all lanes
  double flow_per_lane_veh_per_h() const { return flow_veh_per_h / lanes; }
  double density_per_lane_veh_per_km() const { return density_veh_per_km / lanes; }
};

// Intervals of `interval_s` from `from_s` up to `to_s` (a last partial interval is dropped) for the
// crossings of `dir` at one detector. An interval without vehicles has flow and density 0 and
// speeds 0.
std::vector<DetectorInterval> aggregate_crossings(const std::vector<Crossing>& crossings, double detector_m,
                                                  Direction dir, int lanes, double from_s, double to_s,
                                                  double interval_s);

}  // namespace entourage
