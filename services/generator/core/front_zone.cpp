#include "generator/core/front_zone.hpp"

#include <algorithm>
#include <cmath>

#include "traffic/driving.hpp"

namespace entourage::generator {

void FrontZone::add(const Vehicle& v) { add(v, v.speed_mps); }

void FrontZone::add(const Vehicle& v, double stream_speed_mps) {
  Handoff h;
  h.vehicle = v;
  fleet_.adopt(h, 0, 0.0);
  stream_speed_mps_[v.id] = stream_speed_mps;
}

void FrontZone::move(const LaneIndex& index, double dt_s) {
  std::vector<double> next;
  next.reserve(fleet_.size());
  for (const Vehicle& v : fleet_.vehicles()) {
    const IdmParams& p = v.driver.car_following.idm;
    double target = stream_speed_mps_[v.id];
    if (const Occupant* leader = nearest_leader(v, index)) {
      const double gap = std::max(0.0, gap_between(*leader, v.progress_m(), v.length_m));
      const double room = std::max(0.0, gap - p.min_gap_m);
      target = std::min({target, leader->speed_mps + std::sqrt(2.0 * p.comfort_decel_mps2 * room),
                         room / p.time_gap_s});
    }
    const double lo = std::max(0.0, v.speed_mps - v.driver.max_decel_mps2 * dt_s);
    next.push_back(std::clamp(target, lo, v.speed_mps + p.max_accel_mps2 * dt_s));
  }
  auto& vehicles = fleet_.vehicles();
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    Vehicle& v = vehicles[i];
    v.accel_mps2 = (next[i] - v.speed_mps) / dt_s;
    v.speed_mps = next[i];
    v.s_m += sign(v.direction) * v.speed_mps * dt_s;
    continue_lane_change(v, dt_s);
  }
}

std::vector<Vehicle> FrontZone::reached_by(double edge_m) {
  auto out = fleet_.extract_if([&](const Vehicle& v) { return v.progress_m() <= edge_m; });
  for (const auto& v : out) stream_speed_mps_.erase(v.id);
  return out;
}

std::vector<Vehicle> FrontZone::beyond(double limit_m) {
  auto out = fleet_.extract_if([&](const Vehicle& v) { return v.progress_m() > limit_m; });
  for (const auto& v : out) stream_speed_mps_.erase(v.id);
  return out;
}

std::vector<Vehicle> FrontZone::remove(VehicleId id) {
  auto out = fleet_.extract_if([&](const Vehicle& v) { return v.id == id; });
  stream_speed_mps_.erase(id);
  return out;
}

}  // namespace entourage::generator
