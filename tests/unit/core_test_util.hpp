#pragma once
// Helpers shared by the core unit tests: a scenario built in code, and the window's ego.

#include <string>

#include "scenario/loader.hpp"
#include "traffic/world.hpp"

namespace entourage::testing {

inline ScenarioConfig minimal_scenario() {
  const auto l = scenario::load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/tests/scenarios/minimal.pbtxt");
  return l.config;
}

inline ScenarioConfig freeway_scenario() {
  const auto l = scenario::load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/freeway.pbtxt");
  return l.config;
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
