#pragma once
// Lateral position of a vehicle on the road, including a lane change under way.

#include "road/road.hpp"
#include "traffic/step_io.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

// Between the centres of `lane` and `target_lane`, `fraction` of the way from the first.
inline double lateral_offset_m(const Road& road, Direction dir, int lane, int target_lane, double fraction) {
  const double d_from = road.lane_center_d(dir, lane);
  if (target_lane == lane) return d_from;
  return d_from + (road.lane_center_d(dir, target_lane) - d_from) * fraction;
}

inline double lateral_offset_m(const Road& road, const Vehicle& v) {
  return lateral_offset_m(road, v.direction, v.lane, v.target_lane(), v.lane_change.lateral_fraction());
}

// The same for a published state.
inline double lateral_offset_m(const Road& road, const VehicleReport& r) {
  return lateral_offset_m(road, r.direction, r.lane, r.target_lane, r.lateral_fraction);
}

}  // namespace entourage
