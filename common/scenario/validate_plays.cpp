#include "scenario/validate_plays.hpp"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>

namespace entourage::scenario::detail {

namespace {

// Between the trigger points the director casts the actors and moves them to their start
// positions; a shorter stretch leaves it no time to do so at any realistic speed.
constexpr double kMinPreparation_m = 100.0;
constexpr double kMaxSpeed_kph = 250.0;
// Two start slots in one lane: at least this far apart centre to centre, and, when both vehicle
// types are known, their half lengths plus kMinSlotGap_m.
constexpr double kMinSlotSpacing_m = 8.0;
constexpr double kMinSlotGap_m = 2.0;
constexpr double kMaxPositionTolerance_m = 100.0;
constexpr double kMaxSpeedTolerance_kph = 50.0;
constexpr double kMaxConditionGap_m = 10000.0;
constexpr double kMaxConditionTtc_s = 600.0;
constexpr double kMaxRate_mps2 = 10.0;
constexpr int kMaxLaneChange = 2;
constexpr double kMinLaneChangeDuration_s = 1.0;
constexpr double kMaxLaneChangeDuration_s = 10.0;
constexpr double kMaxPlayDuration_s = 600.0;
constexpr double kMaxRelease_s = 60.0;
// Waiting longer than this for the start condition beyond trigger point 2 moves the event too far
// from where it was placed (some 600 m at freeway speed).
constexpr double kMaxHandoverWait_s = 20.0;

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// The length of a vehicle type, 0 if the name is empty or unknown.
double type_length(const Scenario& s, const std::string& name) {
  for (const auto& t : s.vehicle_type()) {
    if (!name.empty() && t.name() == name) return t.length_m();
  }
  return 0.0;
}

bool type_exists(const Scenario& s, const std::string& name) {
  return std::any_of(s.vehicle_type().begin(), s.vehicle_type().end(),
                     [&](const VehicleType& t) { return t.name() == name; });
}

// A lane relative to the ego's lane at the handover (forward roles, clear zones): the lane can
// exist only if it lies fewer lanes away than the ego's direction has.
void check_relative_lane(const Cursor& c, int offset, const Road& r) {
  const int n = r.lanes_forward();
  if (std::abs(offset) > n - 1) {
    c.fail("lane_offset", "must be in [" + std::to_string(-(n - 1)) + ", " + std::to_string(n - 1) + "] (got " +
                              std::to_string(offset) + "): lanes relative to the ego's, and the road has " +
                              std::to_string(n) + " lane(s) in the ego's direction (road.lanes_forward)");
  }
}

// A distance from the ego: actors and clear zones lie in the window's inner region, where traffic
// is simulated vehicle by vehicle.
void check_in_inner_region(const Cursor& c, const std::string& field, double value, const Window& w) {
  if (value < -w.inner_behind_m() || value > w.inner_ahead_m()) {
    c.fail(field, "must be in [" + fmt(-w.inner_behind_m()) + ", " + fmt(w.inner_ahead_m()) + "] (got " +
                      fmt(value) + "): it must lie in the window's inner region (window.inner_behind_m behind "
                      "the ego to window.inner_ahead_m ahead of it), where the director controls vehicles");
  }
}

bool check_triggers(const Cursor& pc, const Play& p, const Scenario& s) {
  const bool both = pc.require("trigger1_s_m") & pc.require("trigger2_s_m");
  if (!both) return false;
  pc.range("trigger1_s_m", p.trigger1_s_m(), 0.0, s.road().length_m());
  pc.range("trigger2_s_m", p.trigger2_s_m(), 0.0, s.road().length_m());
  const double room = p.trigger2_s_m() - p.trigger1_s_m();
  if (room <= 0.0) {
    pc.fail("trigger2_s_m", "must lie beyond trigger1_s_m");
  } else if (room < kMinPreparation_m) {
    pc.fail("trigger2_s_m", "must lie at least " + fmt(kMinPreparation_m) + " m beyond trigger1_s_m (got " +
                                fmt(room) + " m): between the trigger points the director casts the actors "
                                "and moves them to their start positions");
  }
  return true;
}

void check_role(const Cursor& rc, const Role& r, const Scenario& s) {
  const Road& road = s.road();
  if (rc.has("type") && !type_exists(s, r.type())) {
    rc.fail("type", "unknown vehicle type " + quoted(r.type()) + " (leave type out for any type)");
  }
  if (r.direction() == BOTH) {
    rc.fail("direction", "a role drives in one direction: FORWARD or BACKWARD (oncoming)");
  } else if (r.direction() == BACKWARD) {
    const int n = road.lanes_backward();
    if (n == 0) {
      rc.fail("direction", "BACKWARD: the road has no oncoming lanes (road.lanes_backward = 0)");
    } else if (r.lane_offset() < 0 || r.lane_offset() > n - 1) {
      rc.fail("lane_offset", "must be in [0, " + std::to_string(n - 1) + "] (got " + std::to_string(r.lane_offset()) +
                                 "): for a BACKWARD role, the oncoming lane (0 its rightmost; road.lanes_backward = " +
                                 std::to_string(n) + ")");
    }
  } else {
    check_relative_lane(rc, r.lane_offset(), road);
  }
  if (rc.require("ahead_m")) check_in_inner_region(rc, "ahead_m", r.ahead_m(), s.window());
  switch (r.speed_case()) {
    case Role::kSpeedKph:
      rc.range("speed_kph", r.speed_kph(), 0.0, kMaxSpeed_kph);
      break;
    case Role::kSpeedOffsetKph:
      rc.range("speed_offset_kph", r.speed_offset_kph(), -kMaxSpeed_kph, kMaxSpeed_kph);
      break;
    case Role::SPEED_NOT_SET:
      rc.fail("speed", "is required: speed_kph (absolute) or speed_offset_kph (relative to the ego's speed)");
      break;
  }
  rc.range("position_tolerance_m", r.position_tolerance_m(), 0.0, kMaxPositionTolerance_m, true);
  rc.range("speed_tolerance_kph", r.speed_tolerance_kph(), 0.0, kMaxSpeedTolerance_kph, true);
}

// Names required and unique within the play; returns the names.
std::set<std::string> check_role_names(const Cursor& pc, const Play& p) {
  std::set<std::string> names;
  if (p.role_size() == 0) pc.fail("role", "a play needs at least one role");
  for (int i = 0; i < p.role_size(); ++i) {
    const Cursor rc = pc.child(p.role(i), "role", i);
    if (p.role(i).name().empty()) {
      rc.fail("name", "is required");
    } else if (!names.insert(p.role(i).name()).second) {
      rc.fail("name", quoted(p.role(i).name()) + " is defined twice in this play");
    }
  }
  return names;
}

// No two roles (nor a role and the ego) may ask for the same place in a lane at the handover.
void check_slots(const Cursor& pc, const Play& p, const Scenario& s) {
  const auto needed = [](double len_a, double len_b) {
    return (len_a > 0.0 && len_b > 0.0) ? std::max(kMinSlotSpacing_m, 0.5 * (len_a + len_b) + kMinSlotGap_m)
                                        : kMinSlotSpacing_m;
  };
  for (int j = 0; j < p.role_size(); ++j) {
    const Role& b = p.role(j);
    if (!b.has_ahead_m()) continue;
    const Cursor rc = pc.child(b, "role", j);
    const double len_b = type_length(s, b.type());
    if (b.direction() == FORWARD && b.lane_offset() == 0) {
      const double min = needed(len_b, s.ego().length_m());
      if (std::abs(b.ahead_m()) < min) {
        rc.fail("ahead_m", "the role stands on the ego: in the ego's lane it must be at least " + fmt(min) +
                               " m ahead of or behind it (got " + fmt(b.ahead_m()) + " m)");
      }
    }
    for (int i = 0; i < j; ++i) {
      const Role& a = p.role(i);
      if (!a.has_ahead_m() || a.direction() != b.direction() || a.lane_offset() != b.lane_offset()) continue;
      const double min = needed(type_length(s, a.type()), len_b);
      const double apart = std::abs(a.ahead_m() - b.ahead_m());
      if (apart < min) {
        rc.fail("ahead_m", "overlaps the start slot of role " + quoted(a.name()) + " in the same lane (" +
                               fmt(apart) + " m apart): start slots in one lane must be at least " + fmt(min) +
                               " m apart centre to centre");
      }
    }
  }
}

void check_speed_action(const Cursor& c, const SpeedAction& a) {
  switch (a.target_case()) {
    case SpeedAction::kSpeedKph:
      c.range("speed_kph", a.speed_kph(), 0.0, kMaxSpeed_kph);
      break;
    case SpeedAction::kSpeedOffsetKph:
      c.range("speed_offset_kph", a.speed_offset_kph(), -kMaxSpeed_kph, kMaxSpeed_kph);
      break;
    case SpeedAction::TARGET_NOT_SET:
      c.fail("target", "is required: speed_kph (absolute, 0 for a stop) or speed_offset_kph (relative to the ego's "
                       "speed when the action starts)");
      break;
  }
  c.range("rate_mps2", a.rate_mps2(), 0.0, kMaxRate_mps2, true);
}

void check_lane_change_action(const Cursor& c, const LaneChangeAction& a) {
  if (c.require("lane_offset") && (a.lane_offset() == 0 || std::abs(a.lane_offset()) > kMaxLaneChange)) {
    c.fail("lane_offset", "must be -2, -1, 1 or 2 (got " + std::to_string(a.lane_offset()) +
                              "): lanes to move, +1 one to the left");
  }
  if (c.has("duration_s")) {
    c.range("duration_s", a.duration_s(), kMinLaneChangeDuration_s, kMaxLaneChangeDuration_s);
  }
}

void check_action(const Cursor& ac, const Action& a, const Play& p, const std::set<std::string>& roles) {
  if (ac.require("role") && roles.count(a.role()) == 0) {
    ac.fail("role", "unknown role " + quoted(a.role()) + " (not a role of this play)");
  }
  ac.range("at_s", a.at_s(), 0.0, kMaxPlayDuration_s);
  const double after_s = p.end().after_s();
  const bool end_valid = after_s > 0.0 && after_s <= kMaxPlayDuration_s;
  if (end_valid && a.at_s() >= after_s && a.at_s() <= kMaxPlayDuration_s) {
    ac.fail("at_s", "the play ends " + fmt(after_s) + " s after the handover (end.after_s): an action at " +
                        fmt(a.at_s()) + " s would never run");
  }
  if (ac.has("when_gap_below_m")) ac.range("when_gap_below_m", a.when_gap_below_m(), 0.0, kMaxConditionGap_m, true);
  if (ac.has("when_ttc_below_s")) ac.range("when_ttc_below_s", a.when_ttc_below_s(), 0.0, kMaxConditionTtc_s, true);
  switch (a.kind_case()) {
    case Action::kSpeed:
      check_speed_action(ac.child(a.speed(), "speed"), a.speed());
      break;
    case Action::kLaneChange:
      check_lane_change_action(ac.child(a.lane_change(), "lane_change"), a.lane_change());
      break;
    case Action::kIndicator:
      if (!a.indicator().has_side()) {
        ac.child(a.indicator(), "indicator").fail("side", "is required: OFF, LEFT or RIGHT");
      }
      break;
    case Action::KIND_NOT_SET:
      ac.fail("kind", "an action needs one of speed, lane_change or indicator");
      break;
  }
}

// The lanes a play uses relative to the ego's lane at the handover (forward roles, their lane
// changes, clear zones) must all exist for one and the same lane of the ego: with the ego's own
// lane they may span at most the lanes of the ego's direction.
class LaneSpan {
 public:
  explicit LaneSpan(int lanes) : lanes_(lanes) {}

  // Adds a lane; false (once, on the first lane that does not fit) with `why` set.
  bool add(int lane, std::string* why) {
    if (reported_) return true;
    lo_ = std::min(lo_, lane);
    hi_ = std::max(hi_, lane);
    if (hi_ - lo_ <= lanes_ - 1) return true;
    reported_ = true;
    *why = "the play's lanes relative to the ego's (its own, 0, included) would run from " + std::to_string(lo_) +
           " to " + std::to_string(hi_) + ": " + std::to_string(hi_ - lo_ + 1) + " lanes, but the road has " +
           std::to_string(lanes_) + " in the ego's direction (road.lanes_forward)";
    return false;
  }

 private:
  int lanes_;
  int lo_ = 0;
  int hi_ = 0;
  bool reported_ = false;
};

bool valid_change(int change) { return change != 0 && std::abs(change) <= kMaxLaneChange; }

// Follows the roles through their lane changes: every lane a role is asked to drive in must exist.
// Lanes already refused on their own are left out (they are reported where they are written).
void check_lane_sequences(const Cursor& pc, const Play& p, const Scenario& s) {
  const Road& road = s.road();
  LaneSpan span(road.lanes_forward());
  std::string why;
  for (int i = 0; i < p.role_size(); ++i) {
    const Role& r = p.role(i);
    if (r.direction() == FORWARD && std::abs(r.lane_offset()) <= road.lanes_forward() - 1 &&
        !span.add(r.lane_offset(), &why)) {
      pc.child(r, "role", i).fail("lane_offset", why);
    }
  }
  for (int i = 0; i < p.clear_size(); ++i) {
    const ClearZone& z = p.clear(i);
    if (std::abs(z.lane_offset()) <= road.lanes_forward() - 1 && !span.add(z.lane_offset(), &why)) {
      pc.child(z, "clear", i).fail("lane_offset", why);
    }
  }
  for (const auto& r : p.role()) {
    const bool forward = r.direction() == FORWARD;
    int lane = r.lane_offset();  // forward: relative to the ego's lane at the handover
    const bool start_exists = forward ? std::abs(lane) <= road.lanes_forward() - 1
                                      : lane >= 0 && lane <= road.lanes_backward() - 1;
    if (r.direction() == BOTH || !start_exists) continue;
    for (int i = 0; i < p.action_size(); ++i) {
      const Action& a = p.action(i);
      if (a.role() != r.name() || !a.has_lane_change() || !valid_change(a.lane_change().lane_offset())) continue;
      lane += a.lane_change().lane_offset();
      const Cursor lc = pc.child(a, "action", i).child(a.lane_change(), "lane_change");
      const std::string to = "takes role " + quoted(r.name()) + " to ";
      if (forward && !span.add(lane, &why)) {
        lc.fail("lane_offset", to + "lane " + std::to_string(lane) + " relative to the ego's: " + why);
        break;
      }
      if (!forward && (lane < 0 || lane > road.lanes_backward() - 1)) {
        lc.fail("lane_offset", to + "oncoming lane " + std::to_string(lane) +
                                   ", which does not exist (road.lanes_backward = " +
                                   std::to_string(road.lanes_backward()) + ")");
        break;
      }
    }
  }
}

void check_clear_zone(const Cursor& zc, const ClearZone& z, const Scenario& s) {
  check_relative_lane(zc, z.lane_offset(), s.road());
  if (!(zc.require("from_m") & zc.require("to_m"))) return;
  check_in_inner_region(zc, "from_m", z.from_m(), s.window());
  check_in_inner_region(zc, "to_m", z.to_m(), s.window());
  if (z.to_m() <= z.from_m()) zc.fail("to_m", "must be greater than from_m");
}

void check_end(const Cursor& pc, const Play& p, const Scenario& s, bool triggers) {
  if (!pc.has("end")) return;
  const PlayEnd& e = p.end();
  const Cursor ec = pc.child(e, "end");
  ec.range("after_s", e.after_s(), 0.0, kMaxPlayDuration_s, true);
  if (ec.has("ego_beyond_s_m")) {
    ec.range("ego_beyond_s_m", e.ego_beyond_s_m(), 0.0, s.road().length_m());
    if (triggers && e.ego_beyond_s_m() <= p.trigger2_s_m()) {
      ec.fail("ego_beyond_s_m", "must lie beyond trigger2_s_m = " + fmt(p.trigger2_s_m()) + " (got " +
                                    fmt(e.ego_beyond_s_m()) + "): the play starts there");
    }
  }
}

void check_play(const Cursor& pc, const Play& p, const Scenario& s) {
  const bool triggers = check_triggers(pc, p, s);
  const std::set<std::string> roles = check_role_names(pc, p);
  for (int i = 0; i < p.role_size(); ++i) check_role(pc.child(p.role(i), "role", i), p.role(i), s);
  check_slots(pc, p, s);
  for (int i = 0; i < p.action_size(); ++i) check_action(pc.child(p.action(i), "action", i), p.action(i), p, roles);
  for (int i = 0; i < p.clear_size(); ++i) check_clear_zone(pc.child(p.clear(i), "clear", i), p.clear(i), s);
  check_lane_sequences(pc, p, s);
  check_end(pc, p, s, triggers);
  pc.range("release_s", p.release_s(), 0.0, kMaxRelease_s);
  pc.range("handover_wait_s", p.handover_wait_s(), 0.0, kMaxHandoverWait_s);
}

}  // namespace

void check_plays(const Cursor& top, const Scenario& s) {
  std::set<std::string> names;
  for (int i = 0; i < s.play_size(); ++i) {
    const Play& p = s.play(i);
    const Cursor pc = top.child(p, "play", i);
    if (p.name().empty()) {
      pc.fail("name", "is required");
    } else if (!names.insert(p.name()).second) {
      pc.fail("name", quoted(p.name()) + " is defined twice");
    }
    check_play(pc, p, s);
  }
}

void check_director(const Cursor& top, const Scenario& s) {
  if (!top.has("director")) return;
  const Director& d = s.director();
  const Cursor c = top.child(d, "director");
  c.range("accel_memory_s", d.accel_memory_s(), 0.0, 60.0, true);
  c.range("max_speed_offset_kph", d.max_speed_offset_kph(), 0.0, kMaxSpeed_kph, true);
  c.range("min_speed_kph", d.min_speed_kph(), 0.0, kMaxSpeed_kph);
  c.range("transport_rate_mps2", d.transport_rate_mps2(), 0.0, 3.0, true);
  c.range("max_jerk_mps3", d.max_jerk_mps3(), 0.0, 20.0, true);
  c.range("lane_change_cost_kph", d.lane_change_cost_kph(), 0.0, kMaxSpeed_kph, true);
  c.range("hidden_margin_m", d.hidden_margin_m(), 0.0, 10000.0, true);
  c.range("beside_wait_ahead_m", d.beside_wait_ahead_m(), -1000.0, 1000.0);
  c.range("beside_approach_s", d.beside_approach_s(), 0.0, 120.0, true);
  c.range("oncoming_gap_m", d.oncoming_gap_m(), 0.0, 100000.0);
}

}  // namespace entourage::scenario::detail
