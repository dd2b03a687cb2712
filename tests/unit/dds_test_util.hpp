#pragma once
// Helpers shared by the DDS-side unit tests (conversions, the region publisher): a small road and
// the sample limits of a scenario on it.

#include "dds/convert.hpp"
#include "road/road.hpp"

namespace entourage::dds::testing {

// 10 km, two lanes forward, one backward, 30 m/s.
inline RoadConfig road_config() {
  RoadConfig c;
  c.length_m = 10000.0;
  c.lanes_forward = 2;
  c.lanes_backward = 1;
  c.speed_limit_mps = 30.0;
  return c;
}

// What a scenario on road_config() with two vehicle types accepts.
inline SampleLimits limits() {
  SampleLimits l;
  l.lanes_forward = 2;
  l.lanes_backward = 1;
  l.vehicle_types = 2;
  return l;
}

}  // namespace entourage::dds::testing
