#pragma once
// Start-time estimation (paper IV): from trigger point 1 on, when will the ego reach trigger
// point 2? The ego's speed and (smoothed) acceleration are extrapolated with the acceleration
// fading out over a memory time tau, so a driver who is speeding up is expected to go on doing
// so for a while, not forever:
//
//   v(t) = max(v_floor, v + a_s tau (1 - exp(-t / tau)))
//   x(t) = integral of v(t) dt
//
// where a_s is the ego's acceleration smoothed over kAccelSmoothing_s (a first-order filter of
// what the ego reports). Each step the estimate is revised from the latest state, so a driver
// who brakes or speeds up during the preparation moves it at once.

#include <cstdint>

namespace entourage::director {

struct StartTimeParams {
  double accel_memory_s = 5.0;    // tau: how long the ego's present acceleration is expected to last
  double accel_smoothing_s = 2.0; // time constant of the acceleration filter
  double floor_speed_mps = 1.0;   // the ego is expected to keep moving at least this fast
  double horizon_s = 3600.0;      // beyond this the estimate is "unknown"
};

struct Prediction {
  double time_s = -1.0;      // seconds from now until the distance is covered; < 0: beyond the horizon
  double speed_mps = 0.0;    // the ego's speed expected then
};

class StartTimeEstimator {
 public:
  explicit StartTimeEstimator(StartTimeParams p = {}) : p_(p) {}

  // The ego's state at one step (dt_s since the previous observation).
  void observe(double speed_mps, double accel_mps2, double dt_s);

  // When the ego will have covered `distance_m` from where it is now, and how fast it will be.
  Prediction predict(double distance_m) const;
  // The speed expected after `t_s`.
  double speed_after(double t_s) const;
  double smoothed_accel_mps2() const { return accel_mps2_; }

 private:
  double distance_after(double t_s) const;

  StartTimeParams p_;
  double speed_mps_ = 0.0;
  double accel_mps2_ = 0.0;
  bool seen_ = false;
};

}  // namespace entourage::director
