#include "traffic/detector_stats.hpp"

#include <cmath>

#include "core/units.hpp"

namespace entourage {

namespace {
// Spot speeds below this are taken as this in the harmonic mean (a stopped vehicle on the
// detector would make the space-mean speed zero and the density infinite).
constexpr double kMinSpotSpeed_mps = 0.1;
}  // namespace

std::vector<DetectorInterval> aggregate_crossings(const std::vector<Crossing>& crossings, double detector_m,
                                                  Direction dir, int lanes, double from_s, double to_s,
                                                  double interval_s) {
  std::vector<DetectorInterval> out;
  if (interval_s <= 0.0 || to_s <= from_s) return out;
  const auto n = static_cast<std::size_t>(std::floor((to_s - from_s) / interval_s + 1e-9));
  out.resize(n);
  std::vector<double> inverse_speed_sum(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    DetectorInterval& d = out[i];
    d.start_s = from_s + static_cast<double>(i) * interval_s;
    d.end_s = d.start_s + interval_s;
    d.detector_m = detector_m;
    d.direction = dir;
    d.lanes = std::max(1, lanes);
  }
  for (const Crossing& c : crossings) {
    if (c.direction != dir || c.time_s < from_s) continue;
    const auto i = static_cast<std::size_t>(std::floor((c.time_s - from_s) / interval_s));
    if (i >= n) continue;
    DetectorInterval& d = out[i];
    ++d.vehicles;
    d.time_mean_speed_mps += c.speed_mps;
    inverse_speed_sum[i] += 1.0 / std::max(kMinSpotSpeed_mps, c.speed_mps);
  }
  for (std::size_t i = 0; i < n; ++i) {
    DetectorInterval& d = out[i];
    if (d.vehicles == 0) continue;
    const double count = static_cast<double>(d.vehicles);
    d.flow_veh_per_h = per_second_to_per_hour(count / interval_s);
    d.time_mean_speed_mps /= count;
    d.space_mean_speed_mps = count / inverse_speed_sum[i];
    d.density_veh_per_km = d.flow_veh_per_h / mps_to_kph(d.space_mean_speed_mps);  // (veh/h) / (km/h)
  }
  return out;
}

}  // namespace entourage
