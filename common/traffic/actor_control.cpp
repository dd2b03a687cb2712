#include "traffic/actor_control.hpp"

namespace entourage {

const char* to_string(ControlMode m) {
  switch (m) {
    case ControlMode::kAutonomous: return "autonomous";
    case ControlMode::kTransported: return "transported";
    case ControlMode::kControlled: return "controlled";
    case ControlMode::kReleasing: return "releasing";
    case ControlMode::kWithdrawn: return "withdrawn";
  }
  return "unknown";
}

bool operator==(const ActorControl& a, const ActorControl& b) {
  return a.mode == b.mode && a.play_id == b.play_id && a.speed_mps == b.speed_mps && a.accel_mps2 == b.accel_mps2 &&
         a.decel_mps2 == b.decel_mps2 && a.max_jerk_mps3 == b.max_jerk_mps3 && a.lane == b.lane &&
         a.force_lane == b.force_lane && a.lane_change_duration_s == b.lane_change_duration_s &&
         a.indicator == b.indicator;
}

}  // namespace entourage
