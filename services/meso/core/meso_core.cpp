#include "meso/core/meso_core.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include "meso/core/meso_lanes.hpp"
#include "traffic/actor_driving.hpp"
#include "traffic/carried_states.hpp"
#include "traffic/driving.hpp"
#include "traffic/lane_changes.hpp"
#include "traffic/overtaking_manoeuvre.hpp"
#include "meso/core/meso_model.hpp"

namespace entourage::meso {

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
      serves_rear_(std::find(regions_.begin(), regions_.end(), Region::kOuterRear) != regions_.end()),
      serves_front_(std::find(regions_.begin(), regions_.end(), Region::kOuterFront) != regions_.end()),
      inbox_(Role::kMeso, regions_),
      index_(scenario.road.lanes_forward, scenario.road.lanes_backward),
      model_(model_params_for(scenario)),
      steps_per_plan_(std::max(1, static_cast<int>(std::lround(model_.update_period_s / scenario.step_s)))),
      env_(scenario),
      unseen_(unseen_oncoming(scenario)) {}

bool MesoCore::serves(Region r) const {
  return (r == Region::kOuterRear && serves_rear_) || (r == Region::kOuterFront && serves_front_);
}

StepOutput MesoCore::step(const StepInput& in) {
  ++counters_.steps;
  adopt(in);
  overtakers_.clear();
  if (env_.two_way()) {  // nobody uses an oncoming lane elsewhere
    const auto& vehicles = fleet_.vehicles();
    for (std::size_t i = 0; i < vehicles.size(); ++i) {
      if (overtaking(vehicles[i])) overtakers_.push_back(i);
    }
  }
  const int into_period = static_cast<int>(in.step % static_cast<Step>(steps_per_plan_));
  const bool planning = into_period == 0;
  const bool someone_overtakes = !overtakers_.empty();
  if (someone_overtakes) ++counters_.overtaking_steps;
  if (planning || someone_overtakes || !alert_.empty()) perceive(in);
  if (planning || !alert_.empty()) {
    ++counters_.planning_steps;
    plan(planning, steps_per_plan_ - into_period);
  }
  if (!planning) confirm_changes();
  drive_overtakers();
  move();
  return hand_off(in);
}

bool MesoCore::overtaking(const Vehicle& v) const {
  const int lanes = env_.lanes(v.direction);
  return v.overtaking.active() || v.lane >= lanes || v.target_lane() >= lanes;
}

bool MesoCore::starts_overtaking(Vehicle& v, double desired_speed_mps) {
  if (!overtakes(v, env_) || !chooses_lanes_freely(v) || overtaking(v)) return false;
  // The driver asks itself every decision interval of simulated time; a plan comes once a period.
  const double elapsed_between_plans_s = (steps_per_plan_ - 1) * scenario_.step_s;
  v.overtaking.next_decision_s = std::max(0.0, v.overtaking.next_decision_s - elapsed_between_plans_s);
  const OvertakingStep ot = overtaking_step(v, index_, env_, desired_speed_mps);
  if (ot.started) return true;  // micro's decision, which draws the same, starts it (drive_overtakers)
  v.overtaking = ot.state;
  v.driver.rng_state = ot.rng_state;
  return false;
}

void MesoCore::drive_overtakers() {
  if (overtakers_.empty()) return;
  auto& vehicles = fleet_.vehicles();
  // Every decision from the same snapshot first, then commit, as micro does.
  std::vector<Decision> decisions;
  decisions.reserve(overtakers_.size());
  for (std::size_t i : overtakers_) decisions.push_back(decide(vehicles[i], index_, env_));
  std::vector<VehicleId> back;  // passes over at this step: planned from the next step on
  for (std::size_t k = 0; k < overtakers_.size(); ++k) {
    Vehicle& v = vehicles[overtakers_[k]];
    const bool was_passing = v.overtaking.active();
    commit(v, decisions[k], scenario_.step_s);
    if (!was_passing && v.overtaking.active()) ++counters_.overtakings_started;
    if (!overtaking(v)) back.push_back(v.id);
  }
  // Back in its lane, a vehicle is planned at the next step rather than at the next update: it
  // would otherwise keep the braking of its return for up to a period, slow down below its new
  // leader and then brake hard for the short gap it made (rural_ego_fast, seed 1: a car held
  // 4.2 m/s^2 for 0.7 s after its pass, braked at 9 m/s^2 at the next plan, and the car returning
  // from an aborted pass behind the one it slowed touched it).
  if (back.empty()) return;
  std::vector<VehicleId> merged;
  merged.reserve(alert_.size() + back.size());
  std::set_union(alert_.begin(), alert_.end(), back.begin(), back.end(), std::back_inserter(merged));
  alert_ = std::move(merged);
}

void MesoCore::adopt(const StepInput& in) {
  newcomers_.clear();
  counters_.adopted += adopt_handoffs(fleet_, inbox_, in.handoffs, in.step, scenario_.step_s, &newcomers_);
  counters_.commands_applied += apply_commands(fleet_, in.commands);
  counters_.duplicate_handoffs = inbox_.duplicates();
}

void MesoCore::confirm_changes() {
  if (newcomers_.empty()) return;
  std::vector<const Vehicle*> joined;
  for (VehicleId id : newcomers_) {
    if (const Vehicle* v = fleet_.find(id)) joined.push_back(v);
  }
  for (Vehicle& v : fleet_.vehicles()) {
    if (overtaking(v)) continue;  // micro's manoeuvre reviews its own moves
    const bool crowded = std::any_of(joined.begin(), joined.end(),
                                     [&](const Vehicle* o) { return crowds_change(v, *o, lane_rules_); });
    if (crowded) {
      call_off_lane_change(v);
      ++counters_.called_off_lane_changes;
    }
  }
}

void MesoCore::perceive(const StepInput& in) {
  build_index(index_, fleet_, in.world_prev, ego_seen(in, scenario_.ego.transparent));
  add_unseen_oncoming(index_, unseen_, WindowBounds::around(in.ego.s_m, scenario_.window).front_edge_m);
}

Ahead MesoCore::ahead_of(const Vehicle& v, bool own_lane_only) const {
  Ahead out;
  if (const Occupant* leader = own_lane_only ? leader_of(v, index_, v.lane) : nearest_leader(v, index_)) {
    out = {std::max(0.0, gap_between(*leader, v.progress_m(), v.length_m)), leader->speed_mps, leader->accel_mps2};
  }
  // A vehicle of the other direction in its lane (an overtaker that has not returned yet) is taken
  // as a standing obstacle: it brakes when it could no longer stop comfortably short of it, as a
  // driver who expects the overtaker to pull back in (micro's overtakers plan on that); not at all
  // when it is already moving back and will be out of the lane before they meet.
  if (const Occupant* o = index_.oncoming(v.direction, v.lane, v.progress_m())) {
    const double gap = std::max(0.0, oncoming_gap(*o, v.progress_m(), v.length_m));
    const bool in_the_way = !out_of_the_way_before_meeting(v, *o, v.lane, gap, v.speed_mps + o->speed_mps, env_);
    if (in_the_way && (out.gap_m < 0.0 || gap < out.gap_m)) out = {gap, 0.0, 0.0, Obstacle::kOncoming};
  }
  const double to_closure = env_.ahead().distance_to_closure_m(v.direction, v.lane, v.s_m) - 0.5 * v.length_m;
  if (to_closure < env_.rules().mandatory_lookahead_m && (out.gap_m < 0.0 || to_closure < out.gap_m)) {
    out = {std::max(0.0, to_closure), 0.0, 0.0, Obstacle::kLaneEnd};  // a standing obstacle
  }
  return out;
}

const EquilibriumSpeed& MesoCore::equilibrium_of(const Vehicle& v) {
  auto it = equilibrium_.find(v.id);
  if (it == equilibrium_.end()) it = equilibrium_.emplace(v.id, EquilibriumSpeed(v.driver.car_following)).first;
  return it->second;
}

const EquilibriumSpeed& MesoCore::equilibrium_at(const Vehicle& v, double desired_speed_mps,
                                                 std::optional<EquilibriumSpeed>& raised) {
  if (desired_speed_mps <= v.driver.desired_speed_mps()) return equilibrium_of(v);
  CarFollowingParams params = v.driver.car_following;
  params.idm.desired_speed_mps = desired_speed_mps;
  return raised.emplace(params);  // two entries computed per plan: a few dozen model evaluations
}

bool MesoCore::alert(VehicleId id) const { return std::binary_search(alert_.begin(), alert_.end(), id); }

bool MesoCore::calls_for_alert(const Vehicle& v, const Ahead& ahead, const MesoSpeed& plan) {
  const bool leader_brakes_hard =
      ahead.gap_m >= 0.0 && ahead.leader_accel_mps2 < -v.driver.car_following.idm.comfort_decel_mps2;
  return plan.emergency || ahead.obstacle == Obstacle::kOncoming || leader_brakes_hard;
}

void MesoCore::plan(bool everyone, int steps_left) {
  const PlanHorizon horizon{scenario_.step_s, steps_left};
  std::vector<VehicleId> still_alert;
  std::vector<std::size_t> starting;  // begin a pass now: driven by micro's model from this step
  // Every plan from the same snapshot first, then commit (gaps do not see this step's plans).
  struct Plan {
    std::size_t index;
    MesoSpeed speed;
    std::optional<int> lane;
    bool call_off;
  };
  std::vector<Plan> plans;
  auto& vehicles = fleet_.vehicles();
  plans.reserve(vehicles.size());
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    Vehicle& v = vehicles[i];
    if (overtaking(v)) continue;  // driven by micro's model (drive_overtakers)
    if (!everyone && !alert(v.id)) continue;
    const double desired = actor_desired_speed_mps(
        v, env_.speeds().desired_speed_mps(v.direction, v.s_m, v.driver.desired_speed_mps(), v.driver.basic_median_mps()));
    if (everyone && starts_overtaking(v, desired)) {
      starting.push_back(i);
      continue;
    }
    const bool call_off = calls_off_change(v, index_, lane_rules_);
    const Ahead ahead = ahead_of(v, call_off);
    std::optional<EquilibriumSpeed> raised;
    const MesoSpeed ms = next_speed(v, equilibrium_at(v, desired, raised), ahead, desired, horizon, model_);
    if (ms.emergency) ++counters_.emergency_stops;
    if (calls_for_alert(v, ahead, ms)) still_alert.push_back(v.id);
    const int must = mandatory_target_lane(v, env_);
    const bool may_change = must >= 0 || chooses_lanes_freely(v);  // actors only where the director asks
    const std::optional<int> lane = may_change ? choose_lane(v, index_, ahead.gap_m, lane_rules_, must) : std::nullopt;
    if (lane && must >= 0) ++counters_.mandatory_lane_changes;
    plans.push_back({i, ms, lane, call_off});
  }
  if (!starting.empty()) {
    const std::vector<std::size_t> passing = std::move(overtakers_);
    overtakers_.clear();
    std::merge(passing.begin(), passing.end(), starting.begin(), starting.end(), std::back_inserter(overtakers_));
  }
  counters_.plans += plans.size();
  counters_.alert_plans += everyone ? 0 : plans.size();
  alert_ = std::move(still_alert);  // in id order, as the fleet
  std::vector<std::size_t> changing;  // vehicles that begin a change in this plan
  for (const Plan& p : plans) {
    Vehicle& v = vehicles[p.index];
    v.accel_mps2 = p.speed.accel_mps2;
    if (p.call_off) {
      call_off_lane_change(v);
      ++counters_.called_off_lane_changes;
    }
    if (!p.lane) continue;
    const LaneChangeState before = v.lane_change;
    v.lane_change = start_moving(v, *p.lane, v.driver.lane_change_duration_s);
    // Two vehicles that chose the same room from the same snapshot (from the lanes on either
    // side): the first in id order takes it.
    if (std::any_of(changing.begin(), changing.end(),
                    [&](std::size_t j) { return crowds_change(v, vehicles[j], lane_rules_); })) {
      v.lane_change = before;
      continue;
    }
    changing.push_back(p.index);
  }
}

void MesoCore::move() {
  const double dt = scenario_.step_s;
  auto& vehicles = fleet_.vehicles();
  auto driven = overtakers_.begin();  // in index order: moved by their own commit
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    if (driven != overtakers_.end() && *driven == i) {
      ++driven;
      continue;
    }
    Vehicle& v = vehicles[i];
    advance_on_ramp(v.s_m, v.speed_mps, v.accel_mps2, v.direction, dt);  // as a reader carries it forward
    continue_lane_change(v, dt);
  }
}

MesoCore::Fate MesoCore::fate_of(const Vehicle& v, Region r, const WindowBounds& w) const {
  const bool withdrawn = v.control.mode == ControlMode::kWithdrawn;
  if (!withdrawn && serves(r)) return Fate::kStays;  // the usual step: on in an outer region served here
  const double margin = scenario_.window.handoff_hysteresis_m;
  // Withdrawn by the director: off the road where the driver cannot see it, in the middle of a
  // pass or not (in the inner region it drives on, as micro would drive it).
  if (withdrawn && r != Region::kInner) return Fate::kTakenOff;
  const bool out_ahead = v.s_m > w.front_edge_m + margin;
  if ((out_ahead && v.direction == Direction::kBackward) || v.s_m < w.rear_edge_m - margin) return Fate::kRetires;
  // An overtaker finishes its pass here first: a handoff does not carry the manoeuvre (micro
  // holds its own overtakers back the same way).
  if (overtaking(v)) return Fate::kStays;
  if (out_ahead) return Fate::kToFrontZone;
  if (r == Region::kInner) return Fate::kToMicro;
  if (r != Region::kOutside && !serves(r)) return Fate::kToOtherMeso;
  return Fate::kStays;
}

StepOutput MesoCore::hand_off(const StepInput& in) {
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  StepOutput out;
  out.states.reserve(fleet_.size());
  // One pass in id order, so both the states and the handoffs come out in id order. Vehicles of the
  // ego's direction leaving ahead go on in the generator's front zone (they are the traffic ahead of
  // the window; published once more, outside); others leaving the window retire (not published).
  std::vector<VehicleId> leaving;  // in id order
  for (const Vehicle& v : fleet_.vehicles()) {
    const Region here = w.region_of(v.s_m);
    const Fate fate = fate_of(v, here, w);
    const Region r = fate == Fate::kToFrontZone ? Region::kOutside : here;
    const bool gone = fate == Fate::kRetires || fate == Fate::kTakenOff;
    if (!gone) out.states.emplace_back(v, r);
    if (fate == Fate::kStays) continue;
    leaving.push_back(v.id);
    Handoff h;
    switch (fate) {
      case Fate::kToFrontZone:
        h = make_handoff(v, in.step, self_, Role::kGenerator, Region::kOutside, HandoffReason::kLeftWindow);
        ++counters_.to_front_zone;
        break;
      case Fate::kRetires:
        h = make_handoff(v, in.step, self_, Role::kNone, Region::kOutside, HandoffReason::kLeftWindow);
        ++counters_.retired;
        break;
      case Fate::kTakenOff:
        h = make_handoff(v, in.step, self_, Role::kNone, Region::kOutside, HandoffReason::kDirector);
        ++counters_.taken_off;
        break;
      case Fate::kToMicro:
        h = make_handoff(v, in.step, self_, Role::kMicro, r, HandoffReason::kBorder);
        ++counters_.to_micro;
        break;
      default:
        h = make_handoff(v, in.step, self_, Role::kMeso, r, HandoffReason::kBorder);
        ++counters_.to_other_meso;
        break;
    }
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
  }
  if (!leaving.empty()) {
    const auto leaves = [&leaving](const Vehicle& v) { return std::binary_search(leaving.begin(), leaving.end(), v.id); };
    for (const Vehicle& v : fleet_.extract_if(leaves)) equilibrium_.erase(v.id);
  }
  return out;
}

}  // namespace entourage::meso
