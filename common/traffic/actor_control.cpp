#include "traffic/actor_control.hpp"

namespace entourage {

const char* to_string(ControlMode m) {
  switch (m) {
    case ControlMode::kAutonomous: return "autonomous";
    case ControlMode::kTransported: return "transported";
    case ControlMode::kControlled: return "controlled";
    case ControlMode::kReleasing: return "releasing";
  }
  return "unknown";
}

}  // namespace entourage
