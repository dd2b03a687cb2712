#pragma once
// A stationary traffic stream of one direction and how a window moving with the ego sees it
// (Wardrop 1952; moving-observer relations as in ../shared/notes/traffic-theory.md).
//
// The demand gives a flow q and the desired-speed distribution g(v) of the vehicles passing a
// fixed point (time-mean), a mixture over vehicle types. Then:
//   density                   k = q E_g[1/v]
//   space-mean distribution   f(v) = (g(v)/v) / E_g[1/v]
//   rear-edge entry rate      q E_g[(1 - u/v)+]   with speeds ~ (v - u) f(v) on v > u
//   front-edge entry rate     q E_g[(u/v - 1)+]   with speeds ~ (u - v) f(v) on v < u
//   oncoming entry rate       q E_g[1 + u/v]      with speeds ~ (v + u) f(v)
// for a window moving at u >= 0. Expectations are evaluated on a fine discretisation of each
// type's truncated normal; draws pick a bin by weight and a uniform point inside it.
//
// This is the free stream: the demand's desired speeds taken as the speeds driven. Interacting
// traffic is slower and structured in platoons; see observed_stream.hpp.

#include <cstdint>
#include <functional>
#include <vector>

#include "core/random.hpp"
#include "scenario/config.hpp"

namespace entourage {

struct SpeedClass {
  std::uint8_t type_index = 0;
  double share = 0.0;  // of the flow
  NormalDist desired_speed_mps;
};

struct SpeedDraw {
  std::uint8_t type_index = 0;
  double speed_mps = 0.0;
};

class StreamModel {
 public:
  // A free stream: every vehicle drives at its desired speed, drawn from the classes.
  StreamModel(double flow_veh_per_s, const std::vector<SpeedClass>& classes);

  double flow_veh_per_s() const { return flow_; }
  double density_per_m() const;
  double rate_rear_per_s(double window_speed_mps) const;
  double rate_front_per_s(double window_speed_mps) const;
  double rate_oncoming_per_s(double window_speed_mps) const;
  double mean_time_speed_mps() const;   // E_g[v]
  double mean_space_speed_mps() const;  // 1 / E_g[1/v]

  SpeedDraw draw_time_mean(Random& rng) const;
  SpeedDraw draw_space_mean(Random& rng) const;
  SpeedDraw draw_rear(Random& rng, double window_speed_mps) const;
  SpeedDraw draw_front(Random& rng, double window_speed_mps) const;
  SpeedDraw draw_oncoming(Random& rng, double window_speed_mps) const;

  // E_g[h(v)] (the flow-weighted mean of h over the stream).
  double expect(const std::function<double(double)>& h) const;

 private:
  struct Bin {
    std::uint8_t type_index;
    double lo_mps;
    double hi_mps;
    double mid_mps;
    double probability;  // under g, over all classes
  };
  SpeedDraw draw_weighted(Random& rng, const std::function<double(double)>& h) const;

  double flow_;
  std::vector<Bin> bins_;
};

// Builds the free stream of one direction of a scenario.
StreamModel make_stream(const ScenarioConfig& sc, Direction dir);

}  // namespace entourage
