#include "traffic/driving_environment.hpp"

namespace entourage {

DrivingEnvironment::DrivingEnvironment(const ScenarioConfig& scenario, DrivingRules rules)
    : rules_(rules),
      speeds_(scenario.road, scenario.speed_adaptation),
      ahead_(scenario.road),
      overtaking_(scenario.overtaking),
      dt_s_(scenario.step_s),
      two_way_(two_way_road(scenario.road)),
      lanes_forward_(scenario.road.lanes_forward),
      lanes_backward_(scenario.road.lanes_backward) {}

}  // namespace entourage
