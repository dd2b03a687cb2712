#include "meso/core/meso_core.hpp"

#include <algorithm>

#include "meso/core/meso_lanes.hpp"
#include "traffic/actor_driving.hpp"
#include "traffic/driving.hpp"
#include "traffic/lane_changes.hpp"
#include "meso/core/meso_model.hpp"

namespace entourage::meso {

std::vector<Region> regions_of_instance(std::uint8_t instance) {
  switch (instance) {
    case kMesoFront: return {Region::kOuterFront};
    case kMesoRear: return {Region::kOuterRear};
    default: return {Region::kOuterRear, Region::kOuterFront};
  }
}

MesoModelParams model_params_for(const ScenarioConfig& scenario) {
  MesoModelParams m;
  for (const VehicleTypeConfig& t : scenario.vehicle_types) {
    m.leader_brake_limit_mps2 = std::max(m.leader_brake_limit_mps2, t.max_decel_mps2);
  }
  return m;
}

MesoCore::MesoCore(const ScenarioConfig& scenario, ServiceId self)
    : scenario_(scenario),
      self_(self),
      regions_(regions_of_instance(self.instance)),
      inbox_(Role::kMeso, regions_),
      index_(scenario.road.lanes_forward, scenario.road.lanes_backward),
      model_(model_params_for(scenario)),
      env_(scenario) {}

bool MesoCore::serves(Region r) const { return std::find(regions_.begin(), regions_.end(), r) != regions_.end(); }

StepOutput MesoCore::step(const StepInput& in) {
  adopt(in);
  perceive(in);
  move();
  return hand_off(in);
}

void MesoCore::adopt(const StepInput& in) {
  counters_.adopted += adopt_handoffs(fleet_, inbox_, in.handoffs, in.step, scenario_.step_s);
  counters_.commands_applied += apply_commands(fleet_, in.commands);
  counters_.duplicate_handoffs = inbox_.duplicates();
}

void MesoCore::perceive(const StepInput& in) {
  build_index(index_, fleet_, in.world_prev, in.ego_prev ? &*in.ego_prev : nullptr);
}

namespace {
// Back to the lane it was leaving (it has hardly moved sideways); the interval before its next
// change starts again.
void call_off_lane_change(Vehicle& v) {
  LaneChangeState& lc = v.lane_change;
  lc.phase = LaneChangePhase::kNone;
  lc.from_lane = lc.to_lane = v.lane;
  lc.phase_elapsed_s = 0.0;
  lc.since_last_change_s = 0.0;
}
}  // namespace

Ahead MesoCore::ahead_of(const Vehicle& v, bool own_lane_only) const {
  Ahead out;
  if (const Occupant* leader = own_lane_only ? leader_of(v, index_, v.lane) : nearest_leader(v, index_)) {
    out = {std::max(0.0, gap_between(*leader, v.progress_m(), v.length_m)), leader->speed_mps};
  }
  // A vehicle of the other direction in its lane (an overtaker that has not returned yet) is taken
  // as a standing obstacle: it brakes when it could no longer stop comfortably short of it, as a
  // driver who expects the overtaker to pull back in (micro's overtakers plan on that).
  if (const Occupant* o = index_.oncoming(v.direction, v.lane, v.progress_m())) {
    const double gap = std::max(0.0, oncoming_gap(*o, v.progress_m(), v.length_m));
    if (out.gap_m < 0.0 || gap < out.gap_m) out = {gap, 0.0};
  }
  const double to_closure = env_.ahead().distance_to_closure_m(v.direction, v.lane, v.s_m) - 0.5 * v.length_m;
  if (to_closure < env_.rules().mandatory_lookahead_m && (out.gap_m < 0.0 || to_closure < out.gap_m)) {
    out = {std::max(0.0, to_closure), 0.0};  // the closed lane ends there: a standing obstacle
  }
  return out;
}

const EquilibriumSpeed& MesoCore::equilibrium_of(const Vehicle& v) {
  auto it = equilibrium_.find(v.id);
  if (it == equilibrium_.end()) it = equilibrium_.emplace(v.id, EquilibriumSpeed(v.driver.car_following)).first;
  return it->second;
}

void MesoCore::move() {
  const double dt = scenario_.step_s;
  // Every decision from the same snapshot first, then commit (gaps do not see this step's moves).
  struct Next {
    double speed_mps;
    std::optional<int> lane;
    bool call_off;
  };
  std::vector<Next> next;
  next.reserve(fleet_.size());
  for (const Vehicle& v : fleet_.vehicles()) {
    const bool call_off = calls_off_change(v, index_, lane_rules_);
    const Ahead ahead = ahead_of(v, call_off);
    const double desired = actor_desired_speed_mps(
        v, env_.speeds().desired_speed_mps(v.direction, v.s_m, v.driver.desired_speed_mps(), v.driver.basic_median_mps()));
    const MesoSpeed ms = next_speed(v, equilibrium_of(v), ahead, desired, dt, model_);
    if (ms.emergency) ++counters_.emergency_stops;
    const int must = mandatory_target_lane(v, env_);
    const bool may_change = must >= 0 || chooses_lanes_freely(v);  // actors only where the director asks
    const std::optional<int> lane = may_change ? choose_lane(v, index_, ahead.gap_m, lane_rules_, must) : std::nullopt;
    if (lane && must >= 0) ++counters_.mandatory_lane_changes;
    next.push_back({ms.speed_mps, lane, call_off});
  }
  auto& vehicles = fleet_.vehicles();
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    Vehicle& v = vehicles[i];
    v.accel_mps2 = (next[i].speed_mps - v.speed_mps) / dt;
    v.speed_mps = next[i].speed_mps;
    v.s_m += sign(v.direction) * v.speed_mps * dt;
    if (next[i].call_off) {
      call_off_lane_change(v);
      ++counters_.called_off_lane_changes;
    }
    continue_lane_change(v, dt);
    if (next[i].lane) v.lane_change = start_moving(v, *next[i].lane, v.driver.lane_change_duration_s);
  }
}

StepOutput MesoCore::hand_off(const StepInput& in) {
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  const double margin = scenario_.window.handoff_hysteresis_m;
  StepOutput out;
  out.states.reserve(fleet_.size());
  // Vehicles of the ego's direction leaving ahead go on in the generator's front zone (they are the
  // traffic ahead of the window); all others leaving the window retire.
  auto ahead = fleet_.extract_if(
      [&](const Vehicle& v) { return v.direction == Direction::kForward && v.s_m > w.front_edge_m + margin; });
  for (const Vehicle& v : ahead) {
    equilibrium_.erase(v.id);
    out.states.push_back({v, Region::kOutside});
    Handoff h = make_handoff(v, in.step, self_, Role::kGenerator, Region::kOutside, HandoffReason::kLeftWindow);
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
    ++counters_.to_front_zone;
  }
  auto retiring = fleet_.extract_if(
      [&](const Vehicle& v) { return v.s_m < w.rear_edge_m - margin || v.s_m > w.front_edge_m + margin; });
  for (const Vehicle& v : retiring) {
    equilibrium_.erase(v.id);
    Handoff h = make_handoff(v, in.step, self_, Role::kNone, Region::kOutside, HandoffReason::kLeftWindow);
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
    ++counters_.retired;
  }
  for (const Vehicle& v : fleet_.vehicles()) out.states.push_back({v, w.region_of(v.s_m)});
  // Both runs (those leaving ahead, then the rest of the fleet) are in id order already: merged,
  // not sorted (a sort moved these large records around at every step).
  const auto by_id = [](const VehicleReport& a, const VehicleReport& b) { return a.id < b.id; };
  std::inplace_merge(out.states.begin(), out.states.begin() + static_cast<std::ptrdiff_t>(ahead.size()),
                     out.states.end(), by_id);
  auto leaving = fleet_.extract_if([&](const Vehicle& v) {
    const Region r = w.region_of(v.s_m);
    return r == Region::kInner || (r != Region::kOutside && !serves(r));
  });
  for (const Vehicle& v : leaving) {
    equilibrium_.erase(v.id);
    const Region r = w.region_of(v.s_m);
    const Role to = r == Region::kInner ? Role::kMicro : Role::kMeso;
    Handoff h = make_handoff(v, in.step, self_, to, r, HandoffReason::kBorder);
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
    ++(to == Role::kMicro ? counters_.to_micro : counters_.to_other_meso);
  }
  std::sort(out.handoffs.begin(), out.handoffs.end(),
            [](const Handoff& a, const Handoff& b) { return a.vehicle.id < b.vehicle.id; });
  return out;
}

}  // namespace entourage::meso
