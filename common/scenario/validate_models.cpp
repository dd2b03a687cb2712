#include "scenario/validate_models.hpp"

#include "behaviour/model_registry.hpp"

namespace entourage::scenario::detail {

namespace {
constexpr double kMaxDesiredSpeed_kph = 250.0;
constexpr double kMaxReactionTime_s = 3.0;
constexpr int kMaxAnticipatedLeaders = 8;  // as far as traffic/driving.cpp anticipates

void check_gipps(const Cursor& c, const Gipps& g) {
  check_optional_normal(c, "reaction_time_s", g.reaction_time_s(), 0.0, kMaxReactionTime_s, true);
  check_optional_normal(c, "max_decel_mps2", g.max_decel_mps2(), 0.0, 15.0, true);
  c.range("leader_decel_estimate_mps2", g.leader_decel_estimate_mps2(), 0.0, 15.0, true);
}

void check_human_driver(const Cursor& c, const HumanDriver& h) {
  // The reaction memory holds HdmMemory::kCapacity steps; longer delays would be cut short.
  check_optional_normal(c, "reaction_time_s", h.reaction_time_s(), 0.0, 2.0, false);
  c.range("anticipated_leaders", h.anticipated_leaders(), 1, kMaxAnticipatedLeaders);
  c.range("distance_error", h.distance_error(), 0.0, 1.0);
  c.range("inverse_ttc_error_per_s", h.inverse_ttc_error_per_s(), 0.0, 1.0);
  c.range("error_persistence_s", h.error_persistence_s(), 0.0, 1000.0);
}

void check_curve(const Cursor& c, const std::string& field,
                 const google::protobuf::RepeatedPtrField<GapProbability>& points) {
  for (int i = 0; i < points.size(); ++i) {
    const Cursor pc = c.child(points.Get(i), field, i);
    const bool both = pc.require("gap_m") & pc.require("probability");
    if (!both) continue;
    pc.range("gap_m", points.Get(i).gap_m(), 0.0, 1e5);
    pc.range("probability", points.Get(i).probability(), 0.0, 1.0);
    if (i > 0 && points.Get(i).gap_m() < points.Get(i - 1).gap_m()) {
      pc.fail("gap_m", "points must be in increasing gap_m");
    }
  }
}
}  // namespace

void check_driver(const Cursor& c, const Driver& d) {
  const auto cf = car_following_model_by_name(d.car_following());
  if (!cf) c.fail("car_following", "unknown model \"" + d.car_following() + "\" (see `entourage models`)");
  if (!lane_change_model_by_name(d.lane_change())) {
    c.fail("lane_change", "unknown model \"" + d.lane_change() + "\" (see `entourage models`)");
  }
  if (c.require("desired_speed_kph")) {
    check_normal(c.child(d.desired_speed_kph(), "desired_speed_kph"), d.desired_speed_kph(), 0.0,
                 kMaxDesiredSpeed_kph, true);
  }
  check_optional_normal(c, "time_gap_s", d.time_gap_s(), 0.0, 10.0, true);
  check_optional_normal(c, "max_accel_mps2", d.max_accel_mps2(), 0.0, 10.0, true);
  check_optional_normal(c, "comfort_decel_mps2", d.comfort_decel_mps2(), 0.0, 10.0, true);
  check_optional_normal(c, "min_gap_m", d.min_gap_m(), 0.0, 20.0, false);
  check_optional_normal(c, "politeness", d.politeness(), 0.0, 1.0, false);
  check_optional_normal(c, "lane_change_duration_s", d.lane_change_duration_s(), 0.0, 15.0, true);
  c.range("accel_exponent", d.accel_exponent(), 0.0, 20.0, true);
  // beta = 1 would cut the interaction off where it is largest (a jump at s = s*): above 1 only.
  c.range("beta", d.beta(), 1.0, 10.0, true);
  c.range("coolness", d.coolness(), 0.0, kMaxCoolness);
  if (cf == CarFollowingModel::kGipps && d.coolness() > 0.0) {
    c.fail("coolness", "the ACC model's heuristic blends with idm or modified_idm, not gipps");
  }
  c.range("change_threshold_mps2", d.change_threshold_mps2(), 0.0, 5.0);
  c.range("right_bias_mps2", d.right_bias_mps2(), -5.0, 5.0);
  c.range("safe_decel_mps2", d.safe_decel_mps2(), 0.0, 15.0, true);
  if (c.has("gipps")) check_gipps(c.child(d.gipps(), "gipps"), d.gipps());
  if (c.has("human_driver")) {
    if (cf == CarFollowingModel::kGipps) {
      c.fail("human_driver", "the Human Driver Model wraps idm or modified_idm, not gipps");
    }
    if (d.coolness() > 0.0) c.fail("coolness", "the ACC model's heuristic is not combined with human_driver");
    check_human_driver(c.child(d.human_driver(), "human_driver"), d.human_driver());
  }
}

void check_speed_adaptation(const Cursor& top, const Scenario& s) {
  if (!top.has("speed_adaptation")) return;
  const SpeedAdaptation& a = s.speed_adaptation();
  const Cursor c = top.child(a, "speed_adaptation");
  c.range("limit_rotation", a.limit_rotation(), 0.0, 10.0);
  c.range("curve_lateral_accel_mps2", a.curve_lateral_accel_mps2(), 0.0, 10.0, true);
  c.range("curve_rotation", a.curve_rotation(), 0.0, 10.0);
  c.range("reference_lane_width_m", a.reference_lane_width_m(), 1.0, 10.0);
  c.range("width_reduction_per_m", a.width_reduction_per_m(), 0.0, 1.0);
  c.range("width_rotation", a.width_rotation(), 0.0, 10.0);
  c.range("approach_decel_mps2", a.approach_decel_mps2(), 0.0, 10.0, true);
}

void check_overtaking(const Cursor& top, const Scenario& s) {
  if (!top.has("overtaking")) return;
  const Overtaking& o = s.overtaking();
  const Cursor c = top.child(o, "overtaking");
  check_curve(c, "flying", o.flying());
  check_curve(c, "accelerated", o.accelerated());
  c.range("flying_min_closing_mps", o.flying_min_closing_mps(), 0.0, 50.0);
  c.range("consider_gap_m", o.consider_gap_m(), 0.0, 1000.0, true);
  c.range("decision_interval_s", o.decision_interval_s(), 0.0, 60.0, true);
  c.range("speed_excess_ratio", o.speed_excess_ratio(), 1.0, 2.0);
  c.range("min_speed_gain_mps", o.min_speed_gain_mps(), 0.0, 50.0);
  c.range("accel_share", o.accel_share(), 0.0, 1.0, true);
  c.range("max_distance_m", o.max_distance_m(), 0.0, 1e5, true);
  c.range("lateral_s", o.lateral_s(), 0.0, 15.0, true);
  c.range("return_time_gap_s", o.return_time_gap_s(), 0.0, 10.0);
  c.range("safety_margin_s", o.safety_margin_s(), 0.0, 60.0);
  c.range("hidden_oncoming_speed_kph", o.hidden_oncoming_speed_kph(), 0.0, 250.0);
  c.range("abort_margin_s", o.abort_margin_s(), 0.0, 60.0);
  c.range("commit_share", o.commit_share(), 0.0, 1.0);
  c.range("return_decel_mps2", o.return_decel_mps2(), 0.0, 15.0, true);
}

}  // namespace entourage::scenario::detail
