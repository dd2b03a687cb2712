#pragma once
// A leader as a car-following model sees it.

namespace entourage {

struct LeaderView {
  double gap_m = 0.0;  // bumper to bumper
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
};

}  // namespace entourage
