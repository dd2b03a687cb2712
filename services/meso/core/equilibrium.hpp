#pragma once
// The speed-gap relation of a driver's car-following model in equilibrium (a = 0 behind a
// leader at the same speed): the model's own fundamental diagram, so that meso vehicles drive
// at the speeds micro would settle to at the same gaps and a vehicle crossing between the regions
// keeps its pace. Tabulated per driver by bisection on the model's acceleration, then read by
// interpolation: a few operations per vehicle and step. An entry is computed when a gap first
// needs it (some 40 model evaluations): a vehicle's gap stays within a few entries while it is in
// meso, and filling all 48 whenever a vehicle entered meso took some 40 % of meso's CPU time on
// the default freeway (entourage-bench-meso).

#include <array>
#include <cstdint>

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
  // The car-following model this is the equilibrium of.
  const CarFollowingParams& params() const { return params_; }

 private:
  static constexpr int kPoints = 48;
  static_assert(kPoints <= 64, "known_ has one bit per entry");
  // Entry i of the table, computed on first use.
  double point(std::size_t i) const;

  CarFollowingParams params_;
  double max_gap_m_ = 0.0;
  double desired_mps_ = 0.0;
  // At gaps max_gap * (i / (kPoints - 1))^2; bit i of known_ tells whether entry i is computed yet
  // (a cache: the table is the same whenever an entry is computed).
  mutable std::array<double, kPoints> speed_mps_{};
  mutable std::uint64_t known_ = ~std::uint64_t{0};  // default-constructed: all zero, all known
};

}  // namespace entourage::meso
