#pragma once
// A leader as a car-following model sees it.

namespace entourage {

struct LeaderView {
  // No default values: an aggregate, so that arrays of views on the hot path cost nothing until
  // they are filled. Initialise all three (LeaderView{gap, speed, accel}, or {} for zeros).
  double gap_m;  // bumper to bumper
  double speed_mps;
  double accel_mps2;
};

}  // namespace entourage
