#pragma once
// Parameters of the Human Driver Model (hdm.hpp). Defaults: the values of Treiber, Kesting &
// Helbing 2006 (reaction time 0.6 s, 3 leaders, V_s 0.1, sigma_r 0.01 /s, persistence 20 s).

namespace entourage {

struct HdmParams {
  double reaction_time_s = 0.6;           // T': decisions are applied this late
  int anticipated_leaders = 3;            // n_a >= 1: leaders the driver reacts to
  double distance_error = 0.1;            // V_s: relative error of the estimated gap
  double inverse_ttc_error_per_s = 0.01;  // sigma_r: error of the estimated inverse time to collision
  double error_persistence_s = 20.0;      // tau~: correlation time of the estimation errors
};

}  // namespace entourage
