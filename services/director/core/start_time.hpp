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
//
// Behind a slower leader it cannot get past (one lane in its direction), a driver slows down well
// before it reaches the leader, and the extrapolation, which knows only the present acceleration,
// puts the start too early: traced on the rural slow truck play (stop 35), the ego closing in on
// the truck at 9 m/s slowed from 24.6 to 19 m/s in the last 18 s, the start came 1.4 s after the
// estimate, and the truck, which cannot change its speed fast, stood 16-24 m beyond its start in 9
// of 50 runs. With a leader the ego is also driven forward as an IDM driver behind it (the leader
// at the speed the caller expects of it, constant: its present one, or an actor's start speed,
// play.cpp; the driver's desired speed the extrapolation's, never below its present speed; the
// reference parameters of Treiber et al. 2000, Table I), and the later of the two arrivals is the
// estimate.

#include <cstdint>
#include <optional>

#include "behaviour/idm.hpp"

namespace entourage::director {

struct StartTimeParams {
  double accel_memory_s = 5.0;    // tau: how long the ego's present acceleration is expected to last
  double accel_smoothing_s = 2.0; // time constant of the acceleration filter
  double floor_speed_mps = 1.0;   // the ego is expected to keep moving at least this fast
  double horizon_s = 3600.0;      // beyond this the estimate is "unknown"
  // How the ego is expected to close in on a slower leader (its desired speed is set per step).
  // Treiber et al. 2000, Table I: v0 (replaced), T 1.6 s, a 0.73 m/s^2, b 1.67 m/s^2, s0 2 m, delta 4.
  IdmParams follower{33.3, 1.6, 0.73, 1.67, 2.0, 4.0};
  double follow_step_s = 0.25;    // integration step of the drive behind the leader
};

// The vehicle ahead of the ego in its lane, bumper to bumper, and its speed.
struct LeaderAhead {
  double gap_m = 0.0;
  double speed_mps = 0.0;
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
  // The same behind `leader` (none: as above): the later of the extrapolation and the drive behind
  // it; unknown (< 0) if the drive behind it stops short of the distance.
  Prediction predict(double distance_m, const std::optional<LeaderAhead>& leader) const;
  // The speed expected after `t_s`.
  double speed_after(double t_s) const;
  double smoothed_accel_mps2() const { return accel_mps2_; }

 private:
  double distance_after(double t_s) const;
  Prediction predict_behind(double distance_m, const LeaderAhead& leader) const;

  StartTimeParams p_;
  double speed_mps_ = 0.0;
  double accel_mps2_ = 0.0;
  bool seen_ = false;
};

}  // namespace entourage::director
