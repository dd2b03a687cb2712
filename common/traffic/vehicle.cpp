#include "traffic/vehicle.hpp"

#include <algorithm>

namespace entourage {

double LaneChangeState::lateral_fraction() const {
  if (phase != LaneChangePhase::kMoving || duration_s <= 0.0) return 0.0;
  const double x = std::clamp(phase_elapsed_s / duration_s, 0.0, 1.0);
  return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}

double LaneChangeState::moving_left_s() const {
  return phase == LaneChangePhase::kMoving ? std::max(0.0, duration_s - phase_elapsed_s) : 0.0;
}

Indicator indicator_of(const LaneChangeState& lc, ControlMode mode, Indicator control_indicator) {
  if (!lc.active() || lc.to_lane == lc.from_lane) {
    // A controlled actor shows what its script asks (e.g. before a cut-in).
    return mode == ControlMode::kControlled ? control_indicator : Indicator::kOff;
  }
  // Lane numbers grow to the left for both directions.
  return lc.to_lane > lc.from_lane ? Indicator::kLeft : Indicator::kRight;
}

Indicator Vehicle::indicator() const {
  return indicator_of(lane_change, control.mode, static_cast<Indicator>(control.indicator));
}

}  // namespace entourage
