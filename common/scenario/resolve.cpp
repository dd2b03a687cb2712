#include "scenario/resolve.hpp"

#include <cstdint>
#include <string>

#include "behaviour/gipps.hpp"
#include "core/units.hpp"
#include "scenario/scenario.pb.h"

namespace entourage::scenario {

namespace {

// Defaults of driver parameters left out of a scenario (see scenario.proto).
constexpr double kDefaultTimeGap_s = 1.5;
constexpr double kDefaultMaxAccel_mps2 = 1.0;
constexpr double kDefaultComfortDecel_mps2 = 1.5;
constexpr double kDefaultMinGap_m = 2.0;
constexpr double kDefaultPoliteness = 0.2;
constexpr double kDefaultLaneChangeDuration_s = 4.0;
// Defaults of the Gipps and HDM parameters drawn per driver (the structs' defaults).
const GippsParams kDefaultGipps{};
const HdmParams kDefaultHdm{};

NormalDist to_dist(const Normal& n, double scale = 1.0) {
  NormalDist d;
  d.mean = n.mean() * scale;
  d.sd = n.sd() * scale;
  d.min = (n.has_min() ? n.min() : n.mean() - 3.0 * n.sd()) * scale;
  d.max = (n.has_max() ? n.max() : n.mean() + 3.0 * n.sd()) * scale;
  return d;
}

NormalDist dist_or(bool has, const Normal& n, double constant) {
  if (has) return to_dist(n);
  return NormalDist{constant, 0.0, constant, constant};
}

DriverPopulation resolve_driver(const Driver& d) {
  DriverPopulation p;
  p.car_following = d.car_following();
  p.lane_change = d.lane_change();
  p.desired_speed_mps = to_dist(d.desired_speed_kph(), 1.0 / kKphPerMps);
  p.time_gap_s = dist_or(d.has_time_gap_s(), d.time_gap_s(), kDefaultTimeGap_s);
  p.max_accel_mps2 = dist_or(d.has_max_accel_mps2(), d.max_accel_mps2(), kDefaultMaxAccel_mps2);
  p.comfort_decel_mps2 = dist_or(d.has_comfort_decel_mps2(), d.comfort_decel_mps2(), kDefaultComfortDecel_mps2);
  p.min_gap_m = dist_or(d.has_min_gap_m(), d.min_gap_m(), kDefaultMinGap_m);
  p.accel_exponent = d.accel_exponent();
  p.beta = d.beta();
  p.coolness = d.coolness();
  p.politeness = dist_or(d.has_politeness(), d.politeness(), kDefaultPoliteness);
  p.change_threshold_mps2 = d.change_threshold_mps2();
  p.right_bias_mps2 = d.right_bias_mps2();
  p.safe_decel_mps2 = d.safe_decel_mps2();
  p.lane_change_duration_s =
      dist_or(d.has_lane_change_duration_s(), d.lane_change_duration_s(), kDefaultLaneChangeDuration_s);
  const Gipps& g = d.gipps();
  p.gipps_reaction_time_s = dist_or(g.has_reaction_time_s(), g.reaction_time_s(), kDefaultGipps.reaction_time_s);
  p.gipps_max_decel_mps2 = dist_or(g.has_max_decel_mps2(), g.max_decel_mps2(), kDefaultGipps.max_decel_mps2);
  p.gipps_leader_decel_estimate_mps2 = g.leader_decel_estimate_mps2();
  p.human_driver = d.has_human_driver();
  const HumanDriver& h = d.human_driver();
  p.hdm_reaction_time_s = dist_or(h.has_reaction_time_s(), h.reaction_time_s(), kDefaultHdm.reaction_time_s);
  p.hdm.anticipated_leaders = h.anticipated_leaders();
  p.hdm.distance_error = h.distance_error();
  p.hdm.inverse_ttc_error_per_s = h.inverse_ttc_error_per_s();
  p.hdm.error_persistence_s = h.error_persistence_s();
  p.hdm.reaction_time_s = p.hdm_reaction_time_s.mean;
  return p;
}

Direction direction_of(Directions d) { return d == BACKWARD ? Direction::kBackward : Direction::kForward; }

SpeedAdaptationParams resolve_speed_adaptation(const SpeedAdaptation& a) {
  SpeedAdaptationParams p;
  p.limit_rotation = a.limit_rotation();
  p.curve_lateral_accel_mps2 = a.curve_lateral_accel_mps2();
  p.curve_rotation = a.curve_rotation();
  p.reference_lane_width_m = a.reference_lane_width_m();
  p.width_reduction_per_m = a.width_reduction_per_m();
  p.width_rotation = a.width_rotation();
  p.approach_decel_mps2 = a.approach_decel_mps2();
  return p;
}

AcceptanceCurve resolve_curve(const google::protobuf::RepeatedPtrField<GapProbability>& points,
                              const AcceptanceCurve& fallback) {
  if (points.empty()) return fallback;
  AcceptanceCurve c;
  for (const auto& p : points) c.points.emplace_back(p.gap_m(), p.probability());
  return c;
}

OvertakingParams resolve_overtaking(const Overtaking& o) {
  OvertakingParams p;
  p.flying = resolve_curve(o.flying(), p.flying);
  p.accelerated = resolve_curve(o.accelerated(), p.accelerated);
  p.flying_min_closing_mps = o.flying_min_closing_mps();
  p.consider_gap_m = o.consider_gap_m();
  p.decision_interval_s = o.decision_interval_s();
  p.speed_excess_ratio = o.speed_excess_ratio();
  p.min_speed_gain_mps = o.min_speed_gain_mps();
  p.accel_share = o.accel_share();
  p.max_distance_m = o.max_distance_m();
  p.lateral_s = o.lateral_s();
  p.return_time_gap_s = o.return_time_gap_s();
  p.safety_margin_s = o.safety_margin_s();
  p.hidden_oncoming_speed_mps = kph_to_mps(o.hidden_oncoming_speed_kph());
  p.abort_margin_s = o.abort_margin_s();
  p.commit_share = o.commit_share();
  p.return_decel_mps2 = o.return_decel_mps2();
  return p;
}

FlowConfig resolve_flow(const Flow& f, const Scenario& s) {
  FlowConfig out;
  out.flow_veh_per_s = per_hour_to_per_second(f.flow_veh_per_h());
  if (f.has_headways()) {
    out.free_share = f.headways().free_share();
    out.min_headway_s = f.headways().min_headway_s();
  }
  out.type_shares.assign(static_cast<std::size_t>(s.vehicle_type_size()), 0.0);
  double total = 0.0;
  for (const auto& sh : f.mix()) {
    for (int i = 0; i < s.vehicle_type_size(); ++i) {
      if (s.vehicle_type(i).name() == sh.type()) out.type_shares[static_cast<std::size_t>(i)] += sh.share();
    }
    total += sh.share();
  }
  for (auto& x : out.type_shares) x = total > 0.0 ? x / total : 0.0;
  return out;
}

RoadConfig resolve_road(const Road& r) {
  RoadConfig c;
  c.kind = r.kind() == Road::RURAL ? RoadKind::kRural : RoadKind::kFreeway;
  c.length_m = r.length_m();
  c.lanes_forward = r.lanes_forward();
  c.lanes_backward = r.lanes_backward();
  c.lane_width_m = r.lane_width_m();
  c.median_width_m = r.median_width_m();
  c.speed_limit_mps = kph_to_mps(r.speed_limit_kph());
  for (const auto& seg : r.segment()) c.segments.push_back({seg.length_m(), seg.curvature_per_m()});
  for (const auto& z : r.speed_zone()) c.speed_zones.push_back({z.start_m(), z.end_m(), kph_to_mps(z.limit_kph())});
  for (const auto& z : r.no_overtaking()) {
    c.no_overtaking.push_back({z.start_m(), z.end_m(), z.directions() != BACKWARD, z.directions() != FORWARD});
  }
  for (const auto& l : r.lane_closure()) {
    c.lane_closures.push_back({direction_of(l.direction()), l.lane(), l.start_m(), l.end_m()});
  }
  c.sight_clearance_m = r.sight_clearance_m();
  return c;
}

EgoConfig resolve_ego(const Ego& e) {
  EgoConfig c;
  c.start_s_m = e.start_s_m();
  c.lane = e.lane();
  c.start_speed_mps = e.has_start_speed_kph() ? kph_to_mps(e.start_speed_kph()) : -1.0;
  c.length_m = e.length_m();
  c.width_m = e.width_m();
  c.transparent = e.transparent();
  const EgoIdmDriver& d = e.idm();  // defaults when the ego uses a speed profile
  c.driver.desired_speed_mps = kph_to_mps(d.desired_speed_kph());
  c.driver.time_gap_s = d.time_gap_s();
  c.driver.max_accel_mps2 = d.max_accel_mps2();
  c.driver.comfort_decel_mps2 = d.comfort_decel_mps2();
  c.driver.min_gap_m = d.min_gap_m();
  c.driver.lane_changes = d.lane_changes();
  c.driver.politeness = d.politeness();
  c.driver.coolness = d.coolness();
  for (const auto& st : d.stop()) c.driver.stops.push_back({st.at_s(), st.duration_s(), st.speed_kph() / 3.6});
  if (e.has_speed_profile()) {
    c.driver.use_speed_profile = true;
    for (const auto& p : e.speed_profile().point()) c.driver.profile.emplace_back(p.s_m(), kph_to_mps(p.speed_kph()));
  }
  return c;
}

int vehicle_type_index(const Scenario& s, const std::string& name) {
  for (int i = 0; i < s.vehicle_type_size(); ++i) {
    if (s.vehicle_type(i).name() == name) return i;
  }
  return -1;
}

PlayRoleConfig resolve_role(const Role& r, const Scenario& s) {
  PlayRoleConfig c;
  c.name = r.name();
  c.type_index = r.has_type() ? vehicle_type_index(s, r.type()) : -1;
  c.direction = direction_of(r.direction());
  c.lane_offset = r.lane_offset();
  c.ahead_m = r.ahead_m();
  c.absolute_speed = r.speed_case() == Role::kSpeedKph;
  c.speed_mps = kph_to_mps(c.absolute_speed ? r.speed_kph() : r.speed_offset_kph());
  c.position_tolerance_m = r.position_tolerance_m();
  c.speed_tolerance_mps = kph_to_mps(r.speed_tolerance_kph());
  return c;
}

int role_index(const Play& p, const std::string& name) {
  for (int i = 0; i < p.role_size(); ++i) {
    if (p.role(i).name() == name) return i;
  }
  return -1;
}

PlayActionConfig resolve_action(const Action& a, const Play& p) {
  PlayActionConfig c;
  c.role = role_index(p, a.role());
  c.at_s = a.at_s();
  c.when_gap_below_m = a.has_when_gap_below_m() ? a.when_gap_below_m() : -1.0;
  c.when_ttc_below_s = a.has_when_ttc_below_s() ? a.when_ttc_below_s() : -1.0;
  switch (a.kind_case()) {
    case Action::kLaneChange:
      c.kind = PlayActionKind::kLaneChange;
      c.lane_offset = a.lane_change().lane_offset();
      c.polite = a.lane_change().polite();
      c.duration_s = a.lane_change().has_duration_s() ? a.lane_change().duration_s() : 0.0;
      break;
    case Action::kIndicator:
      c.kind = PlayActionKind::kIndicator;
      c.indicator = static_cast<std::uint8_t>(a.indicator().side());  // OFF 0, LEFT 1, RIGHT 2 as in config
      break;
    case Action::kSpeed:
    case Action::KIND_NOT_SET: {  // refused by validation
      const SpeedAction& sp = a.speed();
      c.kind = PlayActionKind::kSpeed;
      c.absolute_speed = sp.target_case() != SpeedAction::kSpeedOffsetKph;
      c.speed_mps = kph_to_mps(c.absolute_speed ? sp.speed_kph() : sp.speed_offset_kph());
      c.rate_mps2 = sp.rate_mps2();
      break;
    }
  }
  return c;
}

PlayConfig resolve_play(const Play& p, const Scenario& s, std::uint32_t id) {
  PlayConfig c;
  c.id = id;
  c.name = p.name();
  c.trigger1_s_m = p.trigger1_s_m();
  c.trigger2_s_m = p.trigger2_s_m();
  for (const auto& r : p.role()) c.roles.push_back(resolve_role(r, s));
  for (const auto& a : p.action()) c.actions.push_back(resolve_action(a, p));
  for (const auto& z : p.clear()) c.clear.push_back({z.lane_offset(), z.from_m(), z.to_m()});
  c.end_after_s = p.end().after_s();
  c.end_ego_beyond_s_m = p.end().has_ego_beyond_s_m() ? p.end().ego_beyond_s_m() : -1.0;
  c.release_s = p.release_s();
  c.handover_wait_s = p.handover_wait_s();
  return c;
}

DirectorConfig resolve_director(const Director& d) {
  DirectorConfig c;
  c.accel_memory_s = d.accel_memory_s();
  c.max_speed_offset_mps = kph_to_mps(d.max_speed_offset_kph());
  c.min_speed_mps = kph_to_mps(d.min_speed_kph());
  c.transport_rate_mps2 = d.transport_rate_mps2();
  c.max_jerk_mps3 = d.max_jerk_mps3();
  c.lane_change_cost_mps = kph_to_mps(d.lane_change_cost_kph());
  c.hidden_margin_m = d.hidden_margin_m();
  c.beside_wait_ahead_m = d.beside_wait_ahead_m();
  c.beside_approach_s = d.beside_approach_s();
  c.oncoming_gap_m = d.oncoming_gap_m();
  return c;
}

}  // namespace

ScenarioConfig resolve(const Scenario& s) {
  ScenarioConfig c;
  c.name = s.name();
  c.step_s = s.step_s();
  c.duration_s = s.duration_s();
  c.seed = s.seed();
  c.road = resolve_road(s.road());
  const Window& w = s.window();
  c.window = {w.inner_ahead_m(), w.inner_behind_m(), w.outer_ahead_m(), w.outer_behind_m(), w.handoff_hysteresis_m()};
  for (const auto& t : s.vehicle_type()) {
    VehicleTypeConfig vt;
    vt.name = t.name();
    vt.length_m = t.length_m();
    vt.width_m = t.width_m();
    vt.max_decel_mps2 = t.max_decel_mps2();
    vt.keep_right = t.keep_right();
    vt.driver = resolve_driver(t.driver());
    c.vehicle_types.push_back(vt);
  }
  c.forward = resolve_flow(s.demand().forward(), s);
  c.backward = resolve_flow(s.demand().backward(), s);
  c.demand_regulation_gain = s.demand().regulation_gain();
  c.demand_regulation_whole_window = s.demand().regulation_counts() == Demand::WHOLE_WINDOW;
  c.ego = resolve_ego(s.ego());
  std::uint32_t id = 1;
  for (const auto& p : s.play()) c.plays.push_back(resolve_play(p, s, id++));
  c.director = resolve_director(s.director());
  c.speed_adaptation = resolve_speed_adaptation(s.speed_adaptation());
  c.overtaking = resolve_overtaking(s.overtaking());
  for (const VehicleTypeConfig& t : c.vehicle_types) {
    c.overtaking.follower_max_decel_mps2 = std::min(c.overtaking.follower_max_decel_mps2, t.max_decel_mps2);
  }
  return c;
}

}  // namespace entourage::scenario

