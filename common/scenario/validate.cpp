#include "scenario/validate.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "behaviour/model_registry.hpp"
#include "scenario/scenario.pb.h"
#include "scenario/validate_cursor.hpp"
#include "scenario/validate_models.hpp"
#include "scenario/validate_plays.hpp"

namespace entourage::scenario {

namespace {

using detail::check_driver;
using detail::check_normal;
using detail::Cursor;
using detail::kMaxCoolness;
using detail::fmt;
using detail::Location;
using google::protobuf::TextFormat;

// Limits that keep a scenario physically meaningful (and the models in their valid range).
constexpr double kMaxStep_s = 1.0;
constexpr int kMaxLanes = 4;
constexpr double kMinLaneWidth_m = 2.0;
constexpr double kMaxLaneWidth_m = 6.0;
constexpr double kMaxSpeedLimit_kph = 250.0;
constexpr double kMaxRegulationGain = 50.0;  // beyond this the arrivals are a count controller
constexpr double kMaxCurvature_per_m = 1.0 / 15.0;  // tighter than any road bend
constexpr double kMaxVehicleLength_m = 30.0;
constexpr double kMaxVehicleWidth_m = 3.5;
constexpr double kMaxFlow_veh_per_h = 10000.0;
constexpr double kMaxDesiredSpeed_kph = 250.0;

void check_run(const Cursor& c, const Scenario& s) {
  if (!c.has("name") || s.name().empty()) c.fail("name", "is required");
  c.range("step_s", s.step_s(), 0.0, kMaxStep_s, true);
  c.range("duration_s", s.duration_s(), 0.0, 1e7, true);
}

void check_road(const Cursor& top, const Scenario& s) {
  if (!top.require("road")) return;
  const Road& r = s.road();
  const Cursor c = top.child(r, "road");
  if (c.require("length_m")) c.range("length_m", r.length_m(), 0.0, 1e7, true);
  c.range("lanes_forward", r.lanes_forward(), 1, kMaxLanes);
  c.range("lanes_backward", r.lanes_backward(), 0, kMaxLanes);
  if (r.kind() == Road::RURAL && (r.lanes_forward() != 1 || r.lanes_backward() != 1)) {
    c.fail("kind", "a RURAL road has one lane in each direction (lanes_forward = lanes_backward = 1)");
  }
  c.range("lane_width_m", r.lane_width_m(), kMinLaneWidth_m, kMaxLaneWidth_m);
  c.range("median_width_m", r.median_width_m(), 0.0, 100.0);
  if (c.require("speed_limit_kph")) c.range("speed_limit_kph", r.speed_limit_kph(), 0.0, kMaxSpeedLimit_kph, true);
  for (int i = 0; i < r.segment_size(); ++i) {
    const Cursor sc = c.child(r.segment(i), "segment", i);
    if (sc.require("length_m")) sc.range("length_m", r.segment(i).length_m(), 0.0, 1e7, true);
    sc.range("curvature_per_m", r.segment(i).curvature_per_m(), -kMaxCurvature_per_m, kMaxCurvature_per_m);
  }
  for (int i = 0; i < r.no_overtaking_size(); ++i) {
    const NoOvertakingZone& z = r.no_overtaking(i);
    const Cursor zc = c.child(z, "no_overtaking", i);
    if (!(zc.require("start_m") & zc.require("end_m"))) continue;
    if (z.end_m() <= z.start_m()) zc.fail("end_m", "must be greater than start_m");
  }
  for (int i = 0; i < r.lane_closure_size(); ++i) {
    const LaneClosure& l = r.lane_closure(i);
    const Cursor lc = c.child(l, "lane_closure", i);
    if (!(lc.require("lane") & lc.require("start_m") & lc.require("end_m"))) continue;
    if (l.direction() == BOTH) lc.fail("direction", "a closure is of one direction's lane: FORWARD or BACKWARD");
    const int lanes = l.direction() == BACKWARD ? r.lanes_backward() : r.lanes_forward();
    lc.range("lane", l.lane(), 0, std::max(0, lanes - 1));
    if (lanes < 2) lc.fail("lane", "closing the only lane of a direction leaves no way through");
    if (l.end_m() <= l.start_m()) lc.fail("end_m", "must be greater than start_m");
  }
  c.range("sight_clearance_m", r.sight_clearance_m(), 0.0, 1000.0, true);
  for (int i = 0; i < r.speed_zone_size(); ++i) {
    const SpeedZone& z = r.speed_zone(i);
    const Cursor zc = c.child(z, "speed_zone", i);
    const bool ok = zc.require("start_m") & zc.require("end_m") & zc.require("limit_kph");
    if (!ok) continue;
    zc.range("start_m", z.start_m(), 0.0, r.length_m());
    zc.range("end_m", z.end_m(), 0.0, r.length_m());
    if (z.end_m() <= z.start_m()) zc.fail("end_m", "must be greater than start_m");
    zc.range("limit_kph", z.limit_kph(), 0.0, kMaxSpeedLimit_kph, true);
  }
}

void check_window(const Cursor& top, const Scenario& s) {
  const Window& w = s.window();
  const Cursor c = top.child(w, "window");
  c.range("inner_ahead_m", w.inner_ahead_m(), 10.0, 20000.0);
  c.range("inner_behind_m", w.inner_behind_m(), 10.0, 20000.0);
  c.range("outer_ahead_m", w.outer_ahead_m(), 10.0, 20000.0);
  c.range("outer_behind_m", w.outer_behind_m(), 10.0, 20000.0);
  const double hyst_max = std::min(w.outer_ahead_m(), w.outer_behind_m()) / 2.0;
  c.range("handoff_hysteresis_m", w.handoff_hysteresis_m(), 0.0, hyst_max);
}

std::set<std::string> check_vehicle_types(const Cursor& c, const Scenario& s) {
  std::set<std::string> names;
  if (s.vehicle_type_size() == 0) c.fail("vehicle_type", "at least one vehicle type is required");
  for (int i = 0; i < s.vehicle_type_size(); ++i) {
    const VehicleType& t = s.vehicle_type(i);
    const Cursor tc = c.child(t, "vehicle_type", i);
    if (t.name().empty()) {
      tc.fail("name", "is required");
    } else if (!names.insert(t.name()).second) {
      tc.fail("name", "\"" + t.name() + "\" is defined twice");
    }
    tc.range("length_m", t.length_m(), 0.0, kMaxVehicleLength_m, true);
    tc.range("width_m", t.width_m(), 0.0, kMaxVehicleWidth_m, true);
    tc.range("max_decel_mps2", t.max_decel_mps2(), 1.0, 15.0);
    if (tc.require("driver")) check_driver(tc.child(t.driver(), "driver"), t.driver());
  }
  if (s.vehicle_type_size() > 255) c.fail("vehicle_type", "at most 255 vehicle types");
  return names;
}

void check_flow(const Cursor& c, const Flow& f, const std::set<std::string>& types, int lanes) {
  if (!c.require("flow_veh_per_h")) return;
  c.range("flow_veh_per_h", f.flow_veh_per_h(), 0.0, kMaxFlow_veh_per_h);
  if (f.flow_veh_per_h() > 0.0 && lanes == 0) c.fail("flow_veh_per_h", "there are no lanes in this direction");
  double total = 0.0;
  for (int i = 0; i < f.mix_size(); ++i) {
    const Share& sh = f.mix(i);
    const Cursor mc = c.child(sh, "mix", i);
    if (types.count(sh.type()) == 0) mc.fail("type", "unknown vehicle type \"" + sh.type() + "\"");
    mc.range("share", sh.share(), 0.0, 1e9);
    total += sh.share();
  }
  if (f.flow_veh_per_h() > 0.0 && !(total > 0.0)) c.fail("mix", "a positive flow needs a mix with a positive share");
  if (f.has_headways()) {
    const Headways& h = f.headways();
    const Cursor hc = c.child(h, "headways");
    hc.range("free_share", h.free_share(), 0.0, 1.0, true);
    hc.range("min_headway_s", h.min_headway_s(), 0.0, 10.0);
    if (h.min_headway_s() * f.flow_veh_per_h() / 3600.0 >= 1.0) {
      hc.fail("min_headway_s", "min_headway_s times the flow must stay below 1 (the mean headway is 1/flow)");
    }
  }
}

void check_demand(const Cursor& top, const Scenario& s, const std::set<std::string>& types) {
  if (!top.require("demand")) return;
  const Demand& d = s.demand();
  const Cursor c = top.child(d, "demand");
  if (c.require("forward")) check_flow(c.child(d.forward(), "forward"), d.forward(), types, s.road().lanes_forward());
  if (c.has("backward")) check_flow(c.child(d.backward(), "backward"), d.backward(), types, s.road().lanes_backward());
  c.range("regulation_gain", d.regulation_gain(), 0.0, kMaxRegulationGain);
}

double ego_top_speed_kph(const Ego& e) {
  if (e.has_speed_profile()) {
    double top = 0.0;
    for (const auto& p : e.speed_profile().point()) top = std::max(top, p.speed_kph());
    return top;
  }
  return e.idm().desired_speed_kph();
}

void check_ego(const Cursor& top, const Scenario& s) {
  const Ego& e = s.ego();
  const Cursor c = top.child(e, "ego");
  const Road& r = s.road();
  c.range("start_s_m", e.start_s_m(), 0.0, r.length_m());
  c.range("lane", e.lane(), 0, std::max(0, r.lanes_forward() - 1));
  if (e.has_start_speed_kph()) c.range("start_speed_kph", e.start_speed_kph(), 0.0, kMaxSpeedLimit_kph);
  c.range("length_m", e.length_m(), 0.0, kMaxVehicleLength_m, true);
  c.range("width_m", e.width_m(), 0.0, kMaxVehicleWidth_m, true);
  if (e.transparent() && s.play_size() > 0) {
    c.fail("transparent", "a play is staged around an ego the traffic sees: a transparent ego cannot have plays");
  }
  if (e.has_idm()) {
    const EgoIdmDriver& d = e.idm();
    const Cursor dc = c.child(d, "idm");
    dc.range("desired_speed_kph", d.desired_speed_kph(), 0.0, kMaxDesiredSpeed_kph, true);
    dc.range("time_gap_s", d.time_gap_s(), 0.0, 10.0, true);
    dc.range("max_accel_mps2", d.max_accel_mps2(), 0.0, 10.0, true);
    dc.range("comfort_decel_mps2", d.comfort_decel_mps2(), 0.0, 10.0, true);
    dc.range("min_gap_m", d.min_gap_m(), 0.0, 20.0);
    dc.range("politeness", d.politeness(), 0.0, 1.0);
    dc.range("coolness", d.coolness(), 0.0, kMaxCoolness);
    for (int i = 0; i < d.stop_size(); ++i) {
      const Cursor sc = dc.child(d.stop(i), "stop", i);
      sc.range("at_s", d.stop(i).at_s(), 0.0, s.duration_s());
      sc.range("duration_s", d.stop(i).duration_s(), 0.0, 86400.0);
      if (d.stop(i).speed_kph() >= d.desired_speed_kph()) {
        sc.fail("speed_kph", "must be below the driver's desired_speed_kph (" + std::to_string(d.desired_speed_kph()) + ")");
      }
      sc.range("speed_kph", d.stop(i).speed_kph(), 0.0, 250.0);
      if (i > 0 && d.stop(i).at_s() <= d.stop(i - 1).at_s()) sc.fail("at_s", "stops must have increasing at_s");
    }
  }
  if (e.has_speed_profile()) {
    const SpeedProfile& p = e.speed_profile();
    const Cursor pc = c.child(p, "speed_profile");
    if (p.point_size() == 0) pc.fail("point", "a speed profile needs at least one point");
    for (int i = 0; i < p.point_size(); ++i) {
      const Cursor qc = pc.child(p.point(i), "point", i);
      qc.range("speed_kph", p.point(i).speed_kph(), 0.0, kMaxDesiredSpeed_kph);
      if (i > 0 && p.point(i).s_m() <= p.point(i - 1).s_m()) qc.fail("s_m", "points must have increasing s_m");
    }
  }
  // The ego must not run off the road (with the window ahead) within the scenario's duration.
  const Window& w = s.window();
  const double needed = e.start_s_m() + ego_top_speed_kph(e) / 3.6 * s.duration_s() + w.inner_ahead_m() +
                        w.outer_ahead_m();
  if (needed > r.length_m()) {
    top.child(r, "road").fail("length_m", "too short: the ego (start " + fmt(e.start_s_m()) + " m, up to " +
                                              fmt(ego_top_speed_kph(e)) + " km/h for " + fmt(s.duration_s()) +
                                              " s) and the window ahead need " + fmt(std::ceil(needed)) + " m");
  }
}

}  // namespace

void validate(const Scenario& s, const TextFormat::ParseInfoTree& tree, const std::string& path,
              std::vector<Problem>* problems) {
  const Cursor top(s, &tree, "", Location{1, 1}, path, problems);
  check_run(top, s);
  check_road(top, s);
  check_window(top, s);
  const auto types = check_vehicle_types(top, s);
  check_demand(top, s, types);
  if (s.has_road()) check_ego(top, s);
  detail::check_plays(top, s);
  detail::check_director(top, s);
  detail::check_speed_adaptation(top, s);
  detail::check_overtaking(top, s);
}

}  // namespace entourage::scenario
