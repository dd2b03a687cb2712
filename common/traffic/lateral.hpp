#pragma once
// Lateral position of a vehicle on the road, including a lane change under way.

#include "road/road.hpp"
#include "traffic/step_io.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

inline double lateral_offset_m(const Road& road, const Vehicle& v) {
  const double d_from = road.lane_center_d(v.direction, v.lane);
  if (!v.lane_change.moving()) return d_from;
  const double d_to = road.lane_center_d(v.direction, v.lane_change.to_lane);
  return d_from + (d_to - d_from) * v.lane_change.lateral_fraction();
}

// The same for a published state.
inline double lateral_offset_m(const Road& road, const VehicleReport& r) {
  const double d_from = road.lane_center_d(r.direction, r.lane);
  if (r.target_lane == r.lane) return d_from;
  const double d_to = road.lane_center_d(r.direction, r.target_lane);
  return d_from + (d_to - d_from) * r.lateral_fraction;
}

}  // namespace entourage
