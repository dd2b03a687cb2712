#pragma once
// The speed-gap relation of a driver's car-following model in equilibrium (a = 0 behind a
// leader at the same speed): the model's own fundamental diagram, so that meso vehicles drive
// at the speeds micro would settle to at the same gaps and a vehicle crossing between the regions
// keeps its pace. Tabulated once per driver (when it enters meso) by bisection on the model's
// acceleration, then read by interpolation: a few operations per vehicle and step.

#include <array>

#include "behaviour/car_following.hpp"

namespace entourage::meso {

class EquilibriumSpeed {
 public:
  EquilibriumSpeed() = default;
  explicit EquilibriumSpeed(const CarFollowingParams& p);

  // Equilibrium speed at a bumper-to-bumper gap (0 at or below the minimum gap; the desired
  // speed beyond the table).
  double at(double gap_m) const;
  double max_gap_m() const { return max_gap_m_; }

 private:
  static constexpr int kPoints = 48;
  double max_gap_m_ = 0.0;
  double desired_mps_ = 0.0;
  std::array<double, kPoints> speed_mps_{};  // at gaps max_gap * (i / (kPoints - 1))^2
};

}  // namespace entourage::meso
