#include "traffic/driving_environment.hpp"

namespace entourage {

DrivingEnvironment::DrivingEnvironment(const ScenarioConfig& scenario, DrivingRules rules)
    : rules_(rules),
      speeds_(scenario.road, scenario.speed_adaptation),
      ahead_(scenario.road),
      overtaking_(scenario.overtaking),
      dt_s_(scenario.step_s),
      two_way_(scenario.road.kind == RoadKind::kRural && scenario.road.lanes_backward > 0 &&
               scenario.road.lanes_forward > 0),
      lanes_forward_(scenario.road.lanes_forward),
      lanes_backward_(scenario.road.lanes_backward) {}

}  // namespace entourage
