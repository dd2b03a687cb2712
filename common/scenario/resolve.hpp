#pragma once
// Converts a valid scenario into ScenarioConfig: defaults applied, units converted to SI.

#include "scenario/config.hpp"

namespace entourage::scenario {

class Scenario;

ScenarioConfig resolve(const Scenario& s);

}  // namespace entourage::scenario
