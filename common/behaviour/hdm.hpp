#pragma once
// The Human Driver Model (Treiber, Kesting & Helbing 2006, "Delays, inaccuracies and anticipation
// in microscopic traffic models", Physica A 360, 71-88) wrapped around a base car-following model
// (IDM or the modified IDM):
//   * finite reaction time T': the acceleration applied now is the one decided from the situation
//     T' ago (interpolated between the two decisions around it, so T' need not be a multiple of dt);
//   * estimation errors that persist over time: the driver perceives the gap as
//     s exp(V_s w_s) and the approach rate as dv - s sigma_r w_r, with w_s and w_r independent
//     Wiener-like (Ornstein-Uhlenbeck) processes of unit variance and correlation time tau;
//   * spatial anticipation: the driver reacts to the n nearest leaders (n <= n_a, those it sees),
//       a = a_free(v) + (1 / C_n) sum_{j=1..n} a_int(s_j, v, v - v_j),   C_n = sum_{j=1..n} 1/j^2,
//     with s_j the gap from its front to the rear of the j-th leader and a_int the base model's
//     interaction term (for the modified IDM including its weight w(s_j / s*_j)). In homogeneous
//     traffic of point-like vehicles s_j = j s, so the sum is a_int(s) C_n and the normalisation
//     keeps the base model's equilibrium (approximately for vehicles of finite length). With a
//     single leader in sight it is the base model.
//
// With T' = 0, V_s = sigma_r = 0 and n_a = 1 the HDM is its base model exactly. Entourage leaves
// out the paper's temporal anticipation (extrapolating the situation over T'), and the reaction
// memory is not carried across handoffs (it restarts, filled with the first decision).

#include <array>
#include <cstdint>
#include <cstddef>

#include "behaviour/car_following.hpp"
#include "core/random.hpp"

namespace entourage {

// The estimation-error processes of one driver (stationary: each is standard normal).
struct HdmErrors {
  double w_distance = 0.0;
  double w_approach = 0.0;
};

// Advances both error processes over dt (exact Ornstein-Uhlenbeck update):
//   w(t + dt) = exp(-dt / tau) w(t) + sqrt(1 - exp(-2 dt / tau)) eta,   eta ~ N(0, 1).
void advance_hdm_errors(HdmErrors& e, const HdmParams& p, double dt_s, SmallRandom& rng);

// Acceleration from the situation as this driver perceives it, without the reaction delay:
// `leaders[0..count)` nearest first, gaps measured to each one's rear (at most n_a are used);
// count 0 is a free road.
double hdm_instant_accel_mps2(const CarFollowingParams& base, const HdmParams& p, const HdmErrors& e,
                              double speed_mps, const LeaderView* leaders, std::size_t count);

// The decisions of the last steps, newest first, for the reaction delay.
struct HdmMemory {
  static constexpr std::size_t kCapacity = 24;  // 2.4 s at dt = 0.1 s
  std::array<float, kCapacity> decided_mps2{};
  std::uint8_t count = 0;  // valid entries

  void push(double a_mps2);
  // The decision taken delay_s before the current one (`current_mps2`, not yet pushed), linear
  // between steps; the oldest one known if the memory is shorter than the delay (a vehicle that
  // has just been adopted, or a delay beyond the capacity).
  double delayed(double current_mps2, double delay_s, double dt_s) const;
};

}  // namespace entourage
