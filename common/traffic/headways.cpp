#include "traffic/headways.hpp"

#include <cmath>
#include <limits>

namespace entourage {

double CompositeHeadways::decay_per_s(double flow_veh_per_s) const {
  const double room = 1.0 - min_headway_s * flow_veh_per_s;  // saturated: every headway is Delta
  return room > 0.0 ? free_share * flow_veh_per_s / room : std::numeric_limits<double>::infinity();
}

double CompositeHeadways::share_below(double flow_veh_per_s, double t_s) const {
  if (t_s <= min_headway_s) return 0.0;
  return 1.0 - free_share * std::exp(-decay_per_s(flow_veh_per_s) * (t_s - min_headway_s));
}

double CompositeHeadways::mean_platoon_size(double flow_veh_per_s, double t_s) const {
  const double leaders = 1.0 - share_below(flow_veh_per_s, t_s);
  return leaders > 0.0 ? 1.0 / leaders : std::numeric_limits<double>::infinity();
}

double draw_headway_s(const CompositeHeadways& h, double flow_veh_per_s, Random& rng) {
  if (h.free_share < 1.0 && rng.uniform() >= h.free_share) return h.min_headway_s;  // follows its leader
  return h.min_headway_s + rng.exponential(h.decay_per_s(flow_veh_per_s));
}

}  // namespace entourage
