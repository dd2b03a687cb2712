#include "play_runs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

namespace entourage::bench {

namespace {
constexpr double kDesiredSpreadKph = 15.0;
constexpr double kBrakeToShare = 0.6;
constexpr double kBrakeHold_s = 6.0;
constexpr double kEagerPoliteness = 0.0;
// After the play has ended (or failed) the run goes on this long, for the release.
constexpr double kAfterEnd_s = 2.0;

using director::occupies;

bool share_lane(const ObservedVehicle& a, const ObservedVehicle& b) {
  return occupies(b, a.direction, a.lane) || occupies(b, a.direction, a.target_lane);
}

// In a lane next to the ego's (of its direction, not changing into the ego's), level with it.
bool beside(const ObservedVehicle& v, const EgoObservation& ego) {
  return v.direction == ego.direction && std::abs(v.lane - ego.lane) == 1 && v.target_lane == v.lane &&
         std::abs(v.s_m - ego.s_m) <= kBesideEgo_m;
}

// The speeds of the ego's direction's vehicles in the inner region, summed over steps.
struct SpeedTally {
  double sum_mps = 0.0;
  double count = 0.0;
  void add(const StepInput& in, const ScenarioConfig& sc) {
    const WindowBounds w = WindowBounds::around(in.ego.s_m, sc.window);
    for (const ObservedVehicle& v : in.world_prev) {
      if (v.direction != in.ego.direction || !w.in_inner(v.s_m)) continue;
      sum_mps += v.speed_mps;
      count += 1.0;
    }
  }
  double mean_mps() const { return count > 0.0 ? sum_mps / count : -1.0; }
};

double bumper_gap_m(const ObservedVehicle& a, const ObservedVehicle& b) {
  return std::abs(a.s_m - b.s_m) - 0.5 * (a.length_m + b.length_m);
}

// The traffic trace: every kTrafficTraceSteps steps, the vehicles from kTraceBehind_m behind the
// ego to kTraceAhead_m ahead of it, each as [<]ID@OFFSET/SPEED/L LANE/k TYPE INDEX (< : oncoming;
// the type's index in the scenario's vehicle types), then a lane change's target or the
// indicator, and the director's control (T, C, R, W), a transported vehicle's with the desired
// speed it was last given (T24.3; T* its own) and the lane it was asked into (T*:1).
constexpr Step kTrafficTraceSteps = 20;
constexpr double kTraceBehind_m = 300.0;
constexpr double kTraceAhead_m = 600.0;

const char* control_mark(ControlMode m) {
  switch (m) {
    case ControlMode::kAutonomous: return "";
    case ControlMode::kTransported: return "T";
    case ControlMode::kControlled: return "C";
    case ControlMode::kReleasing: return "R";
    case ControlMode::kWithdrawn: return "W";
  }
  return "?";
}

void trace_traffic(std::FILE* out, const StepInput& in, const std::map<VehicleId, ActorControl>& last_commands) {
  std::vector<ObservedVehicle> near;
  for (const ObservedVehicle& v : in.world_prev) {
    const double ahead_m = sign(in.ego.direction) * (v.s_m - in.ego.s_m);
    if (ahead_m > -kTraceBehind_m && ahead_m < kTraceAhead_m) near.push_back(v);
  }
  std::sort(near.begin(), near.end(),
            [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.s_m < b.s_m; });
  std::fprintf(out, "  t %.1f ego %.0f v %.1f lane %d |", in.ego.time_s, in.ego.s_m, in.ego.speed_mps, in.ego.lane);
  for (const ObservedVehicle& v : near) {
    std::fprintf(out, " %s%u@%+.0f/%.1f/L%d/k%u", v.direction == in.ego.direction ? "" : "<", v.id, v.s_m - in.ego.s_m,
                 v.speed_mps, v.lane, static_cast<unsigned>(v.type_index));
    // A lane change under way shows its target (L0>1), an indicator without one its side (L0<, L0>).
    if (v.lane != v.target_lane) {
      std::fprintf(out, ">%d", v.target_lane);
    } else if (v.indicator != 0) {
      std::fprintf(out, "%s", v.indicator == 1 ? "<" : ">");
    }
    std::fprintf(out, "%s", control_mark(v.control));
    const auto cmd = last_commands.find(v.id);
    if (v.control == ControlMode::kTransported && cmd != last_commands.end()) {
      const ActorControl& c = cmd->second;
      if (c.speed_mps == kOwnDesiredSpeed_mps) {
        std::fprintf(out, "*");
      } else {
        std::fprintf(out, "%.1f", c.speed_mps);
      }
      if (c.lane >= 0) std::fprintf(out, ":%d", c.lane);
    }
  }
  std::fprintf(out, "\n");
}
}  // namespace

std::optional<LeaderGap> leader_gap(const ObservedVehicle& v, const std::vector<ObservedVehicle>& world,
                                    const EgoObservation& ego) {
  const double p = v.progress_m();
  std::optional<LeaderGap> nearest;
  auto consider = [&](double q, double length_m, bool commanded) {
    if (q <= p) return;
    const double gap_m = q - 0.5 * length_m - (p + 0.5 * v.length_m);
    if (!nearest || gap_m < nearest->gap_m) nearest = LeaderGap{gap_m, commanded};
  };
  for (const ObservedVehicle& o : world) {
    if (o.id != v.id && o.direction == v.direction && o.lane == v.lane) {
      consider(o.progress_m(), o.length_m, o.control != ControlMode::kAutonomous);
    }
  }
  if (ego.direction == v.direction && ego.lane == v.lane) consider(ego.progress_m(), ego.length_m, false);
  return nearest;
}

const char* to_string(EgoVariant v) {
  switch (v) {
    case EgoVariant::kSteady: return "steady";
    case EgoVariant::kBrakes: return "brakes";
    case EgoVariant::kChangesLane: return "changes lane";
  }
  return "?";
}

bool measure_play(ScenarioConfig& sc, const std::string& name) {
  const auto it = std::find_if(sc.plays.begin(), sc.plays.end(), [&](const PlayConfig& p) { return p.name == name; });
  if (it == sc.plays.end()) return false;
  std::rotate(sc.plays.begin(), it, it + 1);
  return true;
}

ScenarioConfig vary_ego(ScenarioConfig sc, int index, std::uint64_t seed, EgoVariant* variant) {
  const auto v = static_cast<EgoVariant>(index % 3);
  if (variant != nullptr) *variant = v;
  Random rng = Random::derived(seed, 0xE60ULL);
  EgoDriverConfig& d = sc.ego.driver;
  d.desired_speed_mps = std::max(40.0 / 3.6, d.desired_speed_mps + rng.uniform(-kDesiredSpreadKph, kDesiredSpreadKph) / 3.6);
  sc.ego.start_speed_mps = -1.0;
  if (!sc.plays.empty() && v == EgoVariant::kBrakes) {
    // Halfway between the trigger points at its desired speed.
    const PlayConfig& p = sc.plays.front();
    const double mid_s = 0.5 * (p.trigger1_s_m + p.trigger2_s_m);
    const double at_s = (mid_s - sc.ego.start_s_m) / d.desired_speed_mps;
    d.stops.clear();
    d.stops.push_back({at_s, kBrakeHold_s, kBrakeToShare * d.desired_speed_mps});
  } else if (v == EgoVariant::kChangesLane) {
    d.lane_changes = true;
    d.politeness = kEagerPoliteness;
    d.desired_speed_mps += kDesiredSpreadKph / 3.6;  // faster than most: it passes them
  }
  return sc;
}

void RightPassCounter::observe(const EgoObservation& ego, const std::vector<ObservedVehicle>& world, RightPasses& out,
                               std::FILE* trace) {
  std::map<VehicleId, double> ahead_now;
  if (ego.lane == ego.target_lane) {
    for (const ObservedVehicle& v : world) {
      if (v.direction != ego.direction || v.lane != v.target_lane || v.lane <= ego.lane) continue;
      const double ahead_m = v.progress_m() - ego.progress_m();
      ahead_now.emplace(v.id, ahead_m);
      const auto before = ahead_m_.find(v.id);
      if (before == ahead_m_.end() || before->second <= 0.0 || ahead_m > 0.0) continue;
      ++(v.control == ControlMode::kAutonomous ? out.autonomous : out.commanded);
      if (trace != nullptr) {
        std::fprintf(trace, "passed on the right t %.1f: %u (lane %d, %.1f m/s%s), the ego in lane %d at %.1f m/s\n",
                     ego.time_s, v.id, v.lane, v.speed_mps, control_mark(v.control), ego.lane, ego.speed_mps);
      }
    }
  }
  ahead_m_ = std::move(ahead_now);
}

void LaneChangeCounter::observe(const ObservedVehicle& v, double dt_s) {
  const bool commanded = v.control == ControlMode::kTransported;
  if (!commanded && v.control != ControlMode::kAutonomous) {
    forget(v.id);
    return;
  }
  (commanded ? commanded_s_ : autonomous_s_) += dt_s;
  const auto before = last_.find(v.id);
  if (before != last_.end() && before->second.second == v.control && before->second.first != v.lane) {
    ++(commanded ? made_commanded_ : made_autonomous_)[v.id];
  }
  last_[v.id] = {v.lane, v.control};
}

LaneChangesMade LaneChangeCounter::made(const std::map<VehicleId, int>& by_vehicle, double vehicle_s) {
  LaneChangesMade m;
  m.vehicle_s = vehicle_s;
  for (const auto& [id, n] : by_vehicle) {
    m.count += n;
    m.most_by_one = std::max(m.most_by_one, n);
  }
  m.runs_with_many = m.most_by_one >= kManyLaneChanges ? 1 : 0;
  return m;
}

namespace {
// Has the ego of `in` reached road position `s_m` (along its direction)?
bool ego_passed(const StepInput& in, double s_m) { return in.ego.progress_m() >= sign(in.ego.direction) * s_m; }
}  // namespace

TriggerTimes trigger_times_undirected(const ScenarioConfig& sc, std::uint64_t seed) {
  TriggerTimes t;
  const PlayConfig& play = sc.plays.front();
  ScenarioConfig undirected = sc;
  undirected.plays.clear();
  WindowCores cores(undirected, seed);
  SpeedTally traffic;
  RightPassCounter right_passes;
  for (Step k = 0; k <= undirected.steps() && !cores.at_road_end() && t.trigger2_s < 0.0; ++k) {
    StepInput in = cores.next_input();
    const StepOutputs out = cores.compute(in);
    if (t.trigger1_s < 0.0 && ego_passed(in, play.trigger1_s_m)) t.trigger1_s = in.ego.time_s;
    if (t.trigger2_s < 0.0 && ego_passed(in, play.trigger2_s_m)) t.trigger2_s = in.ego.time_s;
    if (t.trigger1_s >= 0.0 && t.trigger2_s < 0.0) {
      traffic.add(in, undirected);
      if (in.ego_prev) right_passes.observe(*in.ego_prev, in.world_prev, t.passed_on_right);
    }
    cores.publish(in, out);
  }
  if (t.trigger2_s >= 0.0) t.traffic_speed_mps = traffic.mean_mps();
  return t;
}

bool staged_mirrored(const PlayConfig& play, const EgoObservation& ego, const director::Lanes& lanes) {
  return director::mirrored_beside(play, director::staging_lane(ego, lanes), lanes);
}

PlayRunResult run_play(const ScenarioConfig& sc, std::uint64_t seed, std::FILE* trace, std::FILE* traffic) {
  PlayRunResult r;
  WindowCores cores(sc, seed);
  const double dt = sc.step_s;
  const Step last = sc.steps();
  std::map<VehicleId, std::pair<Step, double>> last_accel;  // micro-owned vehicles: (step, accel)
  std::set<std::pair<VehicleId, VehicleId>> overlapping;     // pairs seen overlapping (each counted once)
  std::set<VehicleId> ego_contacts;
  std::map<VehicleId, ActorControl> last_commands;  // for the traffic trace
  std::map<VehicleId, double> beside_since_s;  // vehicles beside the ego now: since when
  struct SignalOn {
    int lane = 0;          // its lane when the indicator came on
    double since_s = 0.0;  // and when
  };
  std::map<VehicleId, SignalOn> signal_lane;  // vehicles signalling now
  LaneChangeCounter lane_changes;
  SpeedTally around_ego;                         // trigger point 1 to 2
  RightPassCounter right_passes;                 // the same
  double first_estimate_s = -1.0;
  bool seen_beyond_trigger2 = false;  // the first report once the ego passed trigger point 2
  const PlayConfig& play = sc.plays.front();
  const director::Lanes lanes{sc.road.lanes_forward, sc.road.lanes_backward};
  double end_time_s = -1.0;
  for (Step k = 0; k <= last && !cores.at_road_end(); ++k) {
    StepInput in = cores.next_input();
    const StepOutputs out = cores.compute(in);
    const WindowBounds w = WindowBounds::around(in.ego.s_m, sc.window);
    if (r.trigger1_time_s < 0.0 && ego_passed(in, play.trigger1_s_m)) r.trigger1_time_s = in.ego.time_s;
    if (r.trigger2_time_s < 0.0 && ego_passed(in, play.trigger2_s_m)) {
      r.trigger2_time_s = in.ego.time_s;
      r.mirrored_at_trigger2 = staged_mirrored(play, in.ego, lanes);
    }
    if (r.trigger1_time_s >= 0.0 && r.trigger2_time_s < 0.0) {
      const bool begins_change = in.ego_prev && in.ego_prev->target_lane == in.ego_prev->lane && in.ego.target_lane != in.ego.lane;
      if (begins_change) ++r.ego_lane_changes;
      around_ego.add(in, sc);
      if (in.ego_prev) right_passes.observe(*in.ego_prev, in.world_prev, r.passed_on_right, trace);
    }
    if (r.trigger2_time_s >= 0.0 && r.traffic_speed_mps < 0.0) r.traffic_speed_mps = around_ego.mean_mps();
    std::set<VehicleId> commanded_now;
    for (const ActorCommand& c : out.director.commands) {
      if (!commanded_now.insert(c.vehicle).second) ++r.commanded_twice_in_a_step;
      last_commands[c.vehicle] = c.control;
    }
    for (const Handoff& h : out.director.births) {
      ++r.created;
      if (w.in_inner(h.vehicle.s_m)) ++r.created_in_view;
    }
    for (const StepOutput* o : {&out.micro, &out.meso}) {
      for (const Handoff& h : o->handoffs) {
        if (h.to_role != Role::kNone || h.reason != HandoffReason::kDirector) continue;
        ++r.taken_off;
        if (h.vehicle.direction == in.ego.direction) ++r.taken_off_for_room;
        if (w.in_inner(h.vehicle.s_m)) ++r.taken_off_in_view;
      }
    }
    for (const director::PlayReport& rep : out.director.reports) {
      if (rep.play_id != sc.plays.front().id) continue;
      if (trace != nullptr) {
        std::fprintf(trace, "t %.1f ego %.0f v %.1f lane %d %s est %.1f pos %.1f spd %.1f %s\n", in.ego.time_s, in.ego.s_m,
                     in.ego.speed_mps, in.ego.lane, director::to_string(rep.phase), rep.estimated_start_time_s,
                     rep.position_error_m, rep.speed_error_mps, rep.detail.c_str());
      }
      r.final_phase = rep.phase;
      const bool with_errors = rep.phase != director::PlayPhase::kWaiting && rep.phase != director::PlayPhase::kPreparing;
      if (r.trigger2_time_s >= 0.0 && r.position_error_at_trigger2_m < 0.0 && with_errors) {
        r.position_error_at_trigger2_m = std::abs(rep.position_error_m);
        r.speed_error_at_trigger2_mps = rep.speed_error_mps;
      }
      if (r.trigger2_time_s >= 0.0 && !seen_beyond_trigger2) {
        seen_beyond_trigger2 = true;
        const std::string waiting = "waiting: ";
        const auto at = rep.detail.find(waiting);
        if (at != std::string::npos) r.missing_at_trigger2 = rep.detail.substr(at + waiting.size());
      }
      if (rep.phase == director::PlayPhase::kPreparing && first_estimate_s < 0.0 && rep.estimated_start_time_s >= 0.0) {
        first_estimate_s = rep.estimated_start_time_s;
      }
      if (rep.phase == director::PlayPhase::kHandedOver || (rep.phase == director::PlayPhase::kFailed && !r.handed_over &&
                                                             r.failure.empty())) {
        r.position_error_m = rep.position_error_m;
        r.speed_error_mps = rep.speed_error_mps;
        if (first_estimate_s >= 0.0) r.estimate_error_s = first_estimate_s - in.ego.time_s;
      }
      if (rep.phase == director::PlayPhase::kHandedOver) {
        r.handed_over = true;
        r.handover_wait_s = r.trigger2_time_s >= 0.0 ? in.ego.time_s - r.trigger2_time_s : 0.0;
        r.handover_beyond_m = sign(in.ego.direction) * (in.ego.s_m - play.trigger2_s_m);
      }
      if (rep.phase == director::PlayPhase::kFailed) r.failure = rep.detail;
      if ((rep.phase == director::PlayPhase::kDone || rep.phase == director::PlayPhase::kFailed) && end_time_s < 0.0) {
        end_time_s = in.ego.time_s + sc.plays.front().release_s + kAfterEnd_s;
      }
    }
    if (traffic != nullptr && k % kTrafficTraceSteps == 0 && r.final_phase != director::PlayPhase::kWaiting) {
      trace_traffic(traffic, in, last_commands);
    }
    // How vehicles in the inner region drove (micro-owned, consecutive steps), and overlaps.
    const bool preparing = r.final_phase == director::PlayPhase::kPreparing || r.final_phase == director::PlayPhase::kCast ||
                           r.final_phase == director::PlayPhase::kTransporting;
    const std::vector<ObservedVehicle>& world = in.world_prev;  // published for k - 1
    const std::vector<VehicleId> actors = cores.director().plays().front().actors();
    // The actors held up behind a leader in their lane (the ego as it was for that world).
    for (VehicleId id : actors) {
      const auto v = std::find_if(world.begin(), world.end(), [&](const ObservedVehicle& o) { return o.id == id; });
      const auto cmd = last_commands.find(id);
      if (!preparing || v == world.end() || v->control != ControlMode::kTransported || cmd == last_commands.end() ||
          cmd->second.speed_mps == kOwnDesiredSpeed_mps || v->speed_mps >= cmd->second.speed_mps - kHeldUpBelow_mps) {
        continue;
      }
      const std::optional<LeaderGap> lead = leader_gap(*v, world, in.ego_prev ? *in.ego_prev : in.ego);
      if (!lead || lead->gap_m > kHeldUpWithin_s * v->speed_mps) continue;
      r.actor_held_up_s += dt;
      if (lead->commanded) r.actor_held_up_by_commanded_s += dt;
    }
    for (const ObservedVehicle& v : world) {
      if (v.owner.role != Role::kMicro) {
        last_accel.erase(v.id);
        continue;
      }
      auto it = last_accel.find(v.id);
      if (it != last_accel.end() && it->second.first + 1 == v.step && preparing) {
        const double jerk = (v.accel_mps2 - it->second.second) / dt;
        if (v.control == ControlMode::kTransported) {
          const bool actor = std::find(actors.begin(), actors.end(), v.id) != actors.end();
          (actor ? r.actors : r.cleared).add(v.accel_mps2, jerk);
        } else if (v.control == ControlMode::kAutonomous) {
          r.autonomous.add(v.accel_mps2, jerk);
        }
      }
      last_accel[v.id] = {v.step, v.accel_mps2};
    }
    // Faster than their type's drivers ever wish (inner region, while preparing).
    for (const ObservedVehicle& v : world) {
      if (!preparing || !w.in_inner(v.s_m) || v.type_index >= sc.vehicle_types.size()) continue;
      if (v.control != ControlMode::kTransported && v.control != ControlMode::kAutonomous) continue;
      const double excess = v.speed_mps - sc.vehicle_types[v.type_index].driver.desired_speed_mps.max;
      if (excess <= 0.0) continue;
      (v.control == ControlMode::kTransported ? r.above_top_commanded : r.above_top_autonomous).add_step(excess, dt);
    }
    // Indicators on and off again in the same lane, and lane changes made (inner region, while preparing).
    for (const ObservedVehicle& v : world) {
      if (!preparing || v.owner.role != Role::kMicro || !w.in_inner(v.s_m) || v.control == ControlMode::kControlled ||
          v.control == ControlMode::kReleasing) {
        signal_lane.erase(v.id);
        lane_changes.forget(v.id);
        continue;
      }
      lane_changes.observe(v, dt);
      SignalsCalledOff& kind = v.control == ControlMode::kAutonomous ? r.called_off_autonomous : r.called_off_commanded;
      kind.vehicle_s += dt;
      const auto on = signal_lane.find(v.id);
      const double now_s = static_cast<double>(v.step) * dt;
      if (v.indicator != 0) {
        if (on == signal_lane.end()) signal_lane.emplace(v.id, SignalOn{v.lane, now_s});
      } else if (on != signal_lane.end()) {
        if (on->second.lane == v.lane) ++kind.count;
        kind.signal_s.push_back(now_s - on->second.since_s);
        signal_lane.erase(on);
      }
    }
    // Those beside the ego now keep the time they came beside it; the others drop out.
    std::map<VehicleId, double> beside_now;
    if (preparing && in.ego_prev) {
      const double now_s = in.ego_prev->time_s;
      for (const ObservedVehicle& v : world) {
        if (!beside(v, *in.ego_prev)) continue;
        const auto before = beside_since_s.find(v.id);
        const double since = before != beside_since_s.end() ? before->second : now_s;
        beside_now.emplace(v.id, since);
        double& longest = v.control == ControlMode::kAutonomous ? r.autonomous_beside_ego_s : r.actor_beside_ego_s;
        longest = std::max(longest, now_s - since);
      }
    }
    beside_since_s = std::move(beside_now);
    for (std::size_t i = 0; i < world.size(); ++i) {
      const ObservedVehicle& a = world[i];
      if (!w.in_inner(a.s_m)) continue;
      for (std::size_t j = i + 1; j < world.size(); ++j) {
        const ObservedVehicle& b = world[j];
        if (!share_lane(a, b) || bumper_gap_m(a, b) >= 0.0) continue;
        if (!overlapping.insert({a.id, b.id}).second) continue;
        const bool actor = a.control != ControlMode::kAutonomous || b.control != ControlMode::kAutonomous;
        if (trace != nullptr) {
          std::fprintf(trace, "overlap t %.1f: %u (s %.1f lane %d to %d, %.1f m/s) and %u (s %.1f lane %d to %d, %.1f m/s)\n",
                       in.ego.time_s, a.id, a.s_m, a.lane, a.target_lane, a.speed_mps, b.id, b.s_m, b.lane,
                       b.target_lane, b.speed_mps);
        }
        ++(actor ? r.overlaps_with_actor : r.overlaps_other);
      }
      if (in.ego_prev && a.control != ControlMode::kAutonomous &&
          (occupies(a, in.ego_prev->direction, in.ego_prev->lane) ||
           occupies(a, in.ego_prev->direction, in.ego_prev->target_lane)) &&
          std::abs(a.s_m - in.ego_prev->s_m) - 0.5 * (a.length_m + in.ego_prev->length_m) < 0.0 &&
          ego_contacts.insert(a.id).second) {
        ++r.ego_contacts_with_actor;
      }
    }
    cores.publish(in, out);
    r.steps = k;
    if (end_time_s >= 0.0 && in.ego.time_s >= end_time_s) break;
  }
  r.lane_changes_commanded = lane_changes.commanded();
  r.lane_changes_autonomous = lane_changes.autonomous();
  return r;
}

RateInterval wilson_interval(int successes, int runs, double z) {
  if (runs <= 0) return {};
  const double n = runs;
  const double p = successes / n;
  const double z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = z * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / (1.0 + z2 / n);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

}  // namespace entourage::bench
