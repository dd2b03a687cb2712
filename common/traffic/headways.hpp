#pragma once
// Arrival headways at a source: Poisson arrivals, or the composite (platoon-forming) distribution
// of Cowan's M3 model (Cowan 1975; the standard model of bunched traffic on two-lane roads): a
// share alpha of the vehicles is free, with a headway of Delta plus an exponential part, the rest
// follow their leader at the minimum headway Delta:
//   P(h <= t) = 1 - alpha exp(-lambda (t - Delta)) for t >= Delta, 0 below,
//   lambda = alpha q / (1 - Delta q),
// so that the mean headway is 1/q (Delta q < 1). alpha = 1 and Delta = 0 is the Poisson stream.

#include "core/random.hpp"

namespace entourage {

struct CompositeHeadways {
  double free_share = 1.0;     // alpha, (0, 1]
  double min_headway_s = 0.0;  // Delta, with Delta * flow < 1

  bool poisson() const { return free_share >= 1.0 && min_headway_s <= 0.0; }
  // lambda of the free headways' exponential part, 1/s.
  double decay_per_s(double flow_veh_per_s) const;
  // P(h < t): the share of headways shorter than t.
  double share_below(double flow_veh_per_s, double t_s) const;
  // The mean size of the platoons (leader included) when a headway below t_s joins a vehicle to
  // the platoon ahead of it: 1 / P(h >= t).
  double mean_platoon_size(double flow_veh_per_s, double t_s) const;
};

// One headway, s.
double draw_headway_s(const CompositeHeadways& h, double flow_veh_per_s, Random& rng);

}  // namespace entourage
