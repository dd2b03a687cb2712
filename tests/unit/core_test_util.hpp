#pragma once
// Helpers shared by the core unit tests: a scenario built in code, and the window's ego.

#include <gtest/gtest.h>

#include <string>

#include "scenario/loader.hpp"
#include "traffic/world.hpp"

namespace entourage::testing {

inline ScenarioConfig minimal_scenario() {
  const auto l = scenario::load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/tests/scenarios/minimal.pbtxt");
  return l.config;
}

// A shipped scenario (scenarios/NAME.pbtxt); a test that loads one that does not load fails.
inline ScenarioConfig shipped_scenario(const std::string& name) {
  const auto l = scenario::load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/" + name + ".pbtxt");
  EXPECT_TRUE(l.ok()) << name;
  return l.config;
}

inline ScenarioConfig freeway_scenario() { return shipped_scenario("freeway"); }

// A straight road of `lanes_forward` + `lanes_backward` lanes (two-way if rural), 10 km long,
// 120 km/h, as a driving environment for hand-built situations.
inline ScenarioConfig road_scenario(int lanes_forward, int lanes_backward, RoadKind kind = RoadKind::kFreeway) {
  ScenarioConfig c;
  c.road.kind = kind;
  c.road.length_m = 10000.0;
  c.road.lanes_forward = lanes_forward;
  c.road.lanes_backward = lanes_backward;
  c.road.speed_limit_mps = 120.0 / 3.6;
  return c;
}

inline EgoObservation ego_at(Step step, double s_m, double speed_mps, int lane = 0) {
  EgoObservation e;
  e.step = step;
  e.time_s = static_cast<double>(step) * 0.1;
  e.s_m = s_m;
  e.speed_mps = speed_mps;
  e.lane = e.target_lane = lane;
  return e;
}

}  // namespace entourage::testing
