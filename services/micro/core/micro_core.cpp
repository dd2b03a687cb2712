#include "micro/core/micro_core.hpp"

namespace entourage::micro {

MicroCore::MicroCore(const ScenarioConfig& scenario, ServiceId self)
    : scenario_(scenario),
      self_(self),
      road_(scenario.road),
      env_(scenario),
      inbox_(Role::kMicro, {Region::kInner}),
      index_(scenario.road.lanes_forward, scenario.road.lanes_backward),
      unseen_(unseen_oncoming(scenario)) {}

StepOutput MicroCore::step(const StepInput& in) {
  adopt(in);
  perceive(in);
  const std::vector<Decision> decisions = decide();
  move(decisions);
  return hand_off(in);
}

void MicroCore::adopt(const StepInput& in) {
  counters_.adopted += adopt_handoffs(fleet_, inbox_, in.handoffs, in.step, scenario_.step_s);
  counters_.commands_applied += apply_commands(fleet_, in.commands);
  counters_.duplicate_handoffs = inbox_.duplicates();
}

void MicroCore::perceive(const StepInput& in) {
  build_index(index_, fleet_, in.world_prev, ego_seen(in, scenario_.ego.transparent));
  add_unseen_oncoming(index_, unseen_, WindowBounds::around(in.ego.s_m, scenario_.window).front_edge_m);
}

std::vector<Decision> MicroCore::decide() const {
  std::vector<Decision> decisions;
  decisions.reserve(fleet_.size());
  for (const Vehicle& v : fleet_.vehicles()) decisions.push_back(entourage::decide(v, index_, env_));
  return decisions;
}

void MicroCore::move(const std::vector<Decision>& decisions) {
  auto& vehicles = fleet_.vehicles();
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    const Decision& d = decisions[i];
    if (d.emergency) ++counters_.emergency_decisions;
    const Vehicle& v = vehicles[i];
    if (!v.lane_change.active() && d.lane_change.active() && !d.overtaking.active()) {
      ++counters_.lane_changes_started;
      if (d.mandatory_change) ++counters_.mandatory_lane_changes;
    }
    if (d.overtaking.started > v.overtaking.started) ++counters_.overtakings_started;
    if (d.overtaking.aborted > v.overtaking.aborted) ++counters_.overtakings_aborted;
    commit(vehicles[i], d, scenario_.step_s);
  }
}

StepOutput MicroCore::hand_off(const StepInput& in) {
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  const double margin = scenario_.window.handoff_hysteresis_m;
  StepOutput out;
  out.states.reserve(fleet_.size());
  for (const Vehicle& v : fleet_.vehicles()) out.states.push_back({v, w.region_of(v.s_m)});

  auto beyond = [&](const Vehicle& v) { return v.s_m < w.inner_rear_m - margin || v.s_m > w.inner_front_m + margin; };
  auto busy = [&](const Vehicle& v) {
    return v.overtaking.active() || v.lane >= road_.lanes(v.direction) || v.target_lane() >= road_.lanes(v.direction);
  };
  for (const Vehicle& v : fleet_.vehicles()) {
    if (beyond(v) && busy(v)) ++counters_.handoffs_deferred;
  }
  auto leaving = fleet_.extract_if([&](const Vehicle& v) { return beyond(v) && !busy(v); });
  for (const Vehicle& v : leaving) {
    const Region to = v.s_m < w.inner_rear_m ? Region::kOuterRear : Region::kOuterFront;
    Handoff h = make_handoff(v, in.step, self_, Role::kMeso, to, HandoffReason::kBorder);
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
    ++counters_.handed_out;
  }
  return out;
}

}  // namespace entourage::micro
