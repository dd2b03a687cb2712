#include "traffic/carried_states.hpp"

#include <algorithm>
#include <cstring>

#include "traffic/driving.hpp"

namespace entourage {

namespace {
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// What a reader sees of a lane change (the driver's own timers travel in handoffs only).
bool same_lane_change(const LaneChangeState& a, const LaneChangeState& b) {
  return a.phase == b.phase && a.from_lane == b.from_lane && a.to_lane == b.to_lane &&
         same_bits(a.phase_elapsed_s, b.phase_elapsed_s) && same_bits(a.duration_s, b.duration_s);
}
}  // namespace

void advance_on_ramp(double& s_m, double& speed_mps, double& accel_mps2, Direction direction, double dt_s) {
  const double next = speed_mps + accel_mps2 * dt_s;
  if (next <= 0.0) accel_mps2 = -speed_mps / dt_s;  // stops within this step, and stays (0 from the next)
  speed_mps = std::max(0.0, next);
  s_m += sign(direction) * speed_mps * dt_s;
}

VehicleReport carried_forward(const VehicleReport& r, double dt_s) {
  VehicleReport next = r;
  advance_on_ramp(next.s_m, next.speed_mps, next.accel_mps2, next.direction, dt_s);
  continue_lane_change(next.lane_change, next.lane, dt_s);
  next.target_lane = target_lane_of(next.lane_change, next.lane);
  next.lateral_fraction = next.lane_change.lateral_fraction();
  next.indicator = indicator_of(next.lane_change, next.control, next.control_indicator);
  return next;
}

bool same_state(const VehicleReport& a, const VehicleReport& b) {
  return a.id == b.id && a.region == b.region && a.type_index == b.type_index && a.direction == b.direction &&
         a.indicator == b.indicator && a.control == b.control && a.lane == b.lane && a.target_lane == b.target_lane &&
         same_bits(a.lateral_fraction, b.lateral_fraction) && same_bits(a.s_m, b.s_m) &&
         same_bits(a.speed_mps, b.speed_mps) && same_bits(a.accel_mps2, b.accel_mps2) &&
         same_bits(a.length_m, b.length_m) && same_bits(a.width_m, b.width_m) &&
         same_lane_change(a.lane_change, b.lane_change) && a.control_indicator == b.control_indicator;
}

SparseStep SparseStates::select(const std::vector<VehicleReport>& states) {
  SparseStep out;
  auto prev = previous_.begin();
  for (const VehicleReport& s : states) {
    for (; prev != previous_.end() && prev->id < s.id; ++prev) out.gone.push_back(prev->id);
    const bool known = prev != previous_.end() && prev->id == s.id;
    if (!known || !same_state(carried_forward(*prev, dt_s_), s)) out.states.push_back(s);
    if (known) ++prev;
  }
  for (; prev != previous_.end(); ++prev) out.gone.push_back(prev->id);
  previous_ = states;
  return out;
}

const std::vector<VehicleReport>& StateTracks::step(const std::vector<VehicleReport>& published,
                                                    const std::vector<VehicleId>& gone) {
  std::vector<VehicleReport> next;
  next.reserve(states_.size() + published.size());
  auto pub = published.begin();
  for (const VehicleReport& s : states_) {
    if (std::binary_search(gone.begin(), gone.end(), s.id)) continue;
    for (; pub != published.end() && pub->id < s.id; ++pub) next.push_back(*pub);
    if (pub != published.end() && pub->id == s.id) {
      next.push_back(*pub++);
    } else {
      next.push_back(carried_forward(s, dt_s_));
    }
  }
  for (; pub != published.end(); ++pub) next.push_back(*pub);
  states_ = std::move(next);
  return states_;
}

}  // namespace entourage
