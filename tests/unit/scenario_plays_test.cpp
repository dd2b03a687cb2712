// Plays and the director's parameters in scenarios: a full play resolves to SI values, and each
// mistake in a play is refused with the field's path and the reason.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scenario/loader.hpp"

namespace entourage::scenario {
namespace {

constexpr double kKph = 1.0 / 3.6;

const std::string kRoad = "road { length_m: 10000 lanes_forward: 2 lanes_backward: 2 speed_limit_kph: 120 }\n";

// A valid scenario (two lanes each way, a car and a truck type) with `rest` appended.
std::string scenario_with(const std::string& rest, const std::string& road = kRoad) {
  return R"(name: "plays"
duration_s: 60
)" + road + R"(vehicle_type {
  name: "car"
  driver { desired_speed_kph { mean: 115 sd: 10 min: 80 max: 150 } }
}
vehicle_type {
  name: "truck"
  length_m: 16.5
  driver { desired_speed_kph { mean: 85 } }
}
demand {
  forward { flow_veh_per_h: 1200 mix { type: "car" share: 1 } }
  backward { flow_veh_per_h: 1000 mix { type: "car" share: 1 } }
}
ego { start_s_m: 1000 idm { desired_speed_kph: 110 } }
)" + rest;
}

// A play with valid triggers and the given body.
std::string play(const std::string& body) {
  return "play {\n  name: \"p\"\n  trigger1_s_m: 2000\n  trigger2_s_m: 2600\n" + body + "}\n";
}

const std::string kRole = "  role { name: \"a\" ahead_m: 50 speed_offset_kph: 0 }\n";

std::string all(const Loaded& l) {
  std::string s;
  for (const auto& p : l.problems) s += p.to_string() + "\n";
  return s;
}

bool has_problem(const Loaded& l, const std::string& field, const std::string& text) {
  for (const auto& p : l.problems) {
    if (p.field == field && p.message.find(text) != std::string::npos) return true;
  }
  return false;
}

const std::string kFullPlay = R"(play {
  name: "cut-in"
  trigger1_s_m: 2000
  trigger2_s_m: 2600
  role {
    name: "lead"
    type: "truck"
    ahead_m: 60
    speed_offset_kph: -10
    position_tolerance_m: 5
    speed_tolerance_kph: 7.2
  }
  role { name: "cutter" lane_offset: 1 ahead_m: -20 speed_kph: 126 }
  role { name: "oncoming" direction: BACKWARD lane_offset: 1 ahead_m: 300 speed_kph: 90 }
  action { role: "cutter" at_s: 1 when_gap_below_m: 30 indicator { side: RIGHT } }
  action {
    role: "cutter"
    at_s: 2
    when_ttc_below_s: 4
    lane_change { lane_offset: -1 duration_s: 3 polite: true }
  }
  action { role: "lead" speed { speed_kph: 0 rate_mps2: 3 } }
  action { role: "lead" speed { speed_offset_kph: 18 } }
  action { role: "cutter" lane_change { lane_offset: 1 } }
  clear { lane_offset: 1 from_m: -50 to_m: 80 }
  end { after_s: 45 ego_beyond_s_m: 3500 }
  release_s: 8
  handover_wait_s: 3
}
play {
  name: "defaults"
  trigger1_s_m: 4000
  trigger2_s_m: 4200
  role { name: "r" ahead_m: 50 speed_offset_kph: 0 }
  action { role: "r" speed { speed_kph: 50 } }
}
director {
  accel_memory_s: 4
  max_speed_offset_kph: 36
  min_speed_kph: 7.2
  transport_rate_mps2: 0.5
  max_jerk_mps3: 3
  lane_change_cost_kph: 10.8
  hidden_margin_m: 80
  beside_wait_ahead_m: -30
  beside_approach_s: 15
  oncoming_gap_m: 0
}
)";

TEST(ScenarioPlays, AFullPlayResolvesToSiValues) {
  const Loaded l = load_text(scenario_with(kFullPlay), "full.pbtxt");
  ASSERT_TRUE(l.ok()) << all(l);
  ASSERT_EQ(l.config.plays.size(), 2U);
  const PlayConfig& p = l.config.plays[0];
  EXPECT_EQ(p.id, 1U);
  EXPECT_EQ(p.name, "cut-in");
  EXPECT_DOUBLE_EQ(p.trigger1_s_m, 2000.0);
  EXPECT_DOUBLE_EQ(p.trigger2_s_m, 2600.0);

  ASSERT_EQ(p.roles.size(), 3U);
  const PlayRoleConfig& lead = p.roles[0];
  EXPECT_EQ(lead.name, "lead");
  EXPECT_EQ(lead.type_index, 1);
  EXPECT_EQ(lead.direction, Direction::kForward);
  EXPECT_EQ(lead.lane_offset, 0);
  EXPECT_DOUBLE_EQ(lead.ahead_m, 60.0);
  EXPECT_FALSE(lead.absolute_speed);
  EXPECT_NEAR(lead.speed_mps, -10.0 * kKph, 1e-12);
  EXPECT_DOUBLE_EQ(lead.position_tolerance_m, 5.0);
  EXPECT_NEAR(lead.speed_tolerance_mps, 2.0, 1e-12);
  const PlayRoleConfig& cutter = p.roles[1];
  EXPECT_EQ(cutter.type_index, -1);
  EXPECT_EQ(cutter.lane_offset, 1);
  EXPECT_DOUBLE_EQ(cutter.ahead_m, -20.0);
  EXPECT_TRUE(cutter.absolute_speed);
  EXPECT_NEAR(cutter.speed_mps, 35.0, 1e-12);
  EXPECT_DOUBLE_EQ(cutter.position_tolerance_m, 10.0);  // defaults
  EXPECT_NEAR(cutter.speed_tolerance_mps, 2.5, 1e-12);
  const PlayRoleConfig& oncoming = p.roles[2];
  EXPECT_EQ(oncoming.direction, Direction::kBackward);
  EXPECT_EQ(oncoming.lane_offset, 1);
  EXPECT_NEAR(oncoming.speed_mps, 25.0, 1e-12);

  ASSERT_EQ(p.actions.size(), 5U);
  const PlayActionConfig& indicate = p.actions[0];
  EXPECT_EQ(indicate.role, 1);
  EXPECT_EQ(indicate.kind, PlayActionKind::kIndicator);
  EXPECT_DOUBLE_EQ(indicate.at_s, 1.0);
  EXPECT_DOUBLE_EQ(indicate.when_gap_below_m, 30.0);
  EXPECT_LT(indicate.when_ttc_below_s, 0.0);
  EXPECT_EQ(indicate.indicator, 2);  // RIGHT
  const PlayActionConfig& cut = p.actions[1];
  EXPECT_EQ(cut.role, 1);
  EXPECT_EQ(cut.kind, PlayActionKind::kLaneChange);
  EXPECT_LT(cut.when_gap_below_m, 0.0);
  EXPECT_DOUBLE_EQ(cut.when_ttc_below_s, 4.0);
  EXPECT_EQ(cut.lane_offset, -1);
  EXPECT_TRUE(cut.polite);
  EXPECT_DOUBLE_EQ(cut.duration_s, 3.0);
  const PlayActionConfig& brake = p.actions[2];
  EXPECT_EQ(brake.role, 0);
  EXPECT_EQ(brake.kind, PlayActionKind::kSpeed);
  EXPECT_DOUBLE_EQ(brake.at_s, 0.0);
  EXPECT_TRUE(brake.absolute_speed);
  EXPECT_DOUBLE_EQ(brake.speed_mps, 0.0);
  EXPECT_DOUBLE_EQ(brake.rate_mps2, 3.0);
  const PlayActionConfig& speed_up = p.actions[3];
  EXPECT_FALSE(speed_up.absolute_speed);
  EXPECT_NEAR(speed_up.speed_mps, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(speed_up.rate_mps2, 2.0);  // default
  const PlayActionConfig& back = p.actions[4];
  EXPECT_EQ(back.lane_offset, 1);
  EXPECT_FALSE(back.polite);
  EXPECT_DOUBLE_EQ(back.duration_s, 0.0);  // the driver's own

  ASSERT_EQ(p.clear.size(), 1U);
  EXPECT_EQ(p.clear[0].lane_offset, 1);
  EXPECT_DOUBLE_EQ(p.clear[0].from_m, -50.0);
  EXPECT_DOUBLE_EQ(p.clear[0].to_m, 80.0);
  EXPECT_DOUBLE_EQ(p.end_after_s, 45.0);
  EXPECT_DOUBLE_EQ(p.end_ego_beyond_s_m, 3500.0);
  EXPECT_DOUBLE_EQ(p.release_s, 8.0);
  EXPECT_DOUBLE_EQ(p.handover_wait_s, 3.0);

  const PlayConfig& d = l.config.plays[1];
  EXPECT_EQ(d.id, 2U);
  EXPECT_DOUBLE_EQ(d.end_after_s, 30.0);
  EXPECT_LT(d.end_ego_beyond_s_m, 0.0);
  EXPECT_DOUBLE_EQ(d.release_s, 5.0);
  EXPECT_DOUBLE_EQ(d.handover_wait_s, 6.0);
  EXPECT_TRUE(d.clear.empty());

  const DirectorConfig& dc = l.config.director;
  EXPECT_DOUBLE_EQ(dc.accel_memory_s, 4.0);
  EXPECT_NEAR(dc.max_speed_offset_mps, 10.0, 1e-12);
  EXPECT_NEAR(dc.min_speed_mps, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(dc.transport_rate_mps2, 0.5);
  EXPECT_DOUBLE_EQ(dc.max_jerk_mps3, 3.0);
  EXPECT_NEAR(dc.lane_change_cost_mps, 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(dc.hidden_margin_m, 80.0);
  EXPECT_DOUBLE_EQ(dc.beside_wait_ahead_m, -30.0);
  EXPECT_DOUBLE_EQ(dc.beside_approach_s, 15.0);
  EXPECT_DOUBLE_EQ(dc.oncoming_gap_m, 0.0);
}

TEST(ScenarioPlays, DirectorDefaultsAreTheSchemas) {
  const Loaded l = load_text(scenario_with(""), "defaults.pbtxt");
  ASSERT_TRUE(l.ok()) << all(l);
  const DirectorConfig& dc = l.config.director;
  EXPECT_DOUBLE_EQ(dc.accel_memory_s, 5.0);
  EXPECT_NEAR(dc.max_speed_offset_mps, 29.0 * kKph, 1e-12);
  EXPECT_NEAR(dc.min_speed_mps, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(dc.transport_rate_mps2, 0.7);
  EXPECT_DOUBLE_EQ(dc.max_jerk_mps3, 2.0);
  EXPECT_NEAR(dc.lane_change_cost_mps, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(dc.hidden_margin_m, 50.0);
  EXPECT_DOUBLE_EQ(dc.beside_wait_ahead_m, 50.0);
  EXPECT_DOUBLE_EQ(dc.beside_approach_s, 25.0);
  const DirectorConfig plain;  // the C++ defaults agree
  EXPECT_DOUBLE_EQ(plain.beside_wait_ahead_m, dc.beside_wait_ahead_m);
  EXPECT_DOUBLE_EQ(plain.beside_approach_s, dc.beside_approach_s);
  EXPECT_DOUBLE_EQ(dc.oncoming_gap_m, 800.0);
  EXPECT_DOUBLE_EQ(plain.oncoming_gap_m, dc.oncoming_gap_m);
}

TEST(ScenarioPlays, AProblemNamesTheLineOfTheField) {
  const Loaded l = load_text(scenario_with(play("  role {\n    name: \"a\"\n    ahead_m: 50\n    speed_kph: 300\n  }\n")),
                             "line.pbtxt");
  bool found = false;
  for (const auto& p : l.problems) {
    if (p.field == "play[0].role[0].speed_kph") {
      found = true;
      EXPECT_EQ(p.line, 25) << p.to_string();
      EXPECT_NE(p.to_string().find("line.pbtxt:25:5: play[0].role[0].speed_kph: must be in [0, 250] (got 300)"),
                std::string::npos)
          << p.to_string();
    }
  }
  EXPECT_TRUE(found) << all(l);
}

struct BadPlay {
  std::string what;
  std::string text;   // appended to the valid scenario
  std::string field;  // the path the problem must name
  std::string reason;  // and a part of its message
  std::string road = kRoad;
};

TEST(ScenarioPlays, EachMistakeIsRefusedWithTheFieldNamed) {
  const std::vector<BadPlay> cases{
      {"play without name", "play { trigger1_s_m: 2000 trigger2_s_m: 2600 " + kRole + "}", "play[0].name",
       "required"},
      {"two plays of one name", play(kRole) + play(kRole), "play[1].name", "\"p\" is defined twice"},
      {"no trigger 1", "play { name: \"p\" trigger2_s_m: 2600 " + kRole + "}", "play[0].trigger1_s_m", "required"},
      {"trigger 2 before trigger 1", "play { name: \"p\" trigger1_s_m: 2600 trigger2_s_m: 2000 " + kRole + "}",
       "play[0].trigger2_s_m", "beyond trigger1_s_m"},
      {"no room to prepare", "play { name: \"p\" trigger1_s_m: 2000 trigger2_s_m: 2050 " + kRole + "}",
       "play[0].trigger2_s_m", "at least 100 m beyond trigger1_s_m (got 50 m): between the trigger points"},
      {"trigger 2 off the road", "play { name: \"p\" trigger1_s_m: 2000 trigger2_s_m: 12000 " + kRole + "}",
       "play[0].trigger2_s_m", "must be in [0, 10000] (got 12000)"},
      {"no role", play(""), "play[0].role", "at least one role"},
      {"role without name", play("  role { ahead_m: 50 speed_kph: 80 }\n"), "play[0].role[0].name", "required"},
      {"two roles of one name", play(kRole + "  role { name: \"a\" ahead_m: 80 speed_kph: 80 }\n"),
       "play[0].role[1].name", "\"a\" is defined twice in this play"},
      {"unknown type", play("  role { name: \"a\" type: \"bus\" ahead_m: 50 speed_kph: 80 }\n"),
       "play[0].role[0].type", "unknown vehicle type \"bus\""},
      {"both directions", play("  role { name: \"a\" direction: BOTH ahead_m: 50 speed_kph: 80 }\n"),
       "play[0].role[0].direction", "FORWARD or BACKWARD"},
      {"oncoming role on a one-way road",
       play("  role { name: \"a\" direction: BACKWARD ahead_m: 50 speed_kph: 80 }\n"), "play[0].role[0].direction",
       "no oncoming lanes",
       "road { length_m: 10000 lanes_forward: 2 lanes_backward: 0 speed_limit_kph: 120 }\n"},
      {"forward lane beyond the road", play("  role { name: \"a\" lane_offset: 2 ahead_m: 50 speed_kph: 80 }\n"),
       "play[0].role[0].lane_offset", "must be in [-1, 1] (got 2)"},
      {"oncoming lane beyond the road",
       play("  role { name: \"a\" direction: BACKWARD lane_offset: 2 ahead_m: 50 speed_kph: 80 }\n"),
       "play[0].role[0].lane_offset", "must be in [0, 1] (got 2)"},
      {"negative oncoming lane",
       play("  role { name: \"a\" direction: BACKWARD lane_offset: -1 ahead_m: 50 speed_kph: 80 }\n"),
       "play[0].role[0].lane_offset", "must be in [0, 1] (got -1)"},
      {"no ahead_m", play("  role { name: \"a\" speed_kph: 80 }\n"), "play[0].role[0].ahead_m", "required"},
      {"role outside the inner region", play("  role { name: \"a\" ahead_m: 500 speed_kph: 80 }\n"),
       "play[0].role[0].ahead_m", "inner region"},
      {"no speed", play("  role { name: \"a\" ahead_m: 50 }\n"), "play[0].role[0].speed",
       "required: speed_kph (absolute) or speed_offset_kph"},
      {"speed too high", play("  role { name: \"a\" ahead_m: 50 speed_kph: 300 }\n"), "play[0].role[0].speed_kph",
       "[0, 250] (got 300)"},
      {"negative speed", play("  role { name: \"a\" ahead_m: 50 speed_kph: -1 }\n"), "play[0].role[0].speed_kph",
       "got -1"},
      {"zero position tolerance", play("  role { name: \"a\" ahead_m: 50 speed_kph: 80 position_tolerance_m: 0 }\n"),
       "play[0].role[0].position_tolerance_m", "(0, 100]"},
      {"zero speed tolerance", play("  role { name: \"a\" ahead_m: 50 speed_kph: 80 speed_tolerance_kph: 0 }\n"),
       "play[0].role[0].speed_tolerance_kph", "got 0"},
      {"role on the ego", play("  role { name: \"a\" ahead_m: 5 speed_kph: 80 }\n"), "play[0].role[0].ahead_m",
       "stands on the ego"},
      {"overlapping slots", play(kRole + "  role { name: \"b\" ahead_m: 45 speed_kph: 80 }\n"),
       "play[0].role[1].ahead_m", "overlaps the start slot of role \"a\" in the same lane (5 m apart)"},
      {"overlapping truck slots",
       play("  role { name: \"a\" type: \"truck\" lane_offset: 1 ahead_m: 50 speed_kph: 80 }\n"
            "  role { name: \"b\" type: \"truck\" lane_offset: 1 ahead_m: 65 speed_kph: 80 }\n"),
       "play[0].role[1].ahead_m", "at least 18.5 m apart"},
      {"action of an unknown role", play(kRole + "  action { role: \"x\" speed { speed_kph: 0 } }\n"),
       "play[0].action[0].role", "unknown role \"x\""},
      {"action without role", play(kRole + "  action { speed { speed_kph: 0 } }\n"), "play[0].action[0].role",
       "required"},
      {"negative at_s", play(kRole + "  action { role: \"a\" at_s: -1 speed { speed_kph: 0 } }\n"),
       "play[0].action[0].at_s", "got -1"},
      {"action after the end", play(kRole + "  action { role: \"a\" at_s: 40 speed { speed_kph: 0 } }\n"),
       "play[0].action[0].at_s", "never run"},
      {"zero gap condition",
       play(kRole + "  action { role: \"a\" when_gap_below_m: 0 speed { speed_kph: 0 } }\n"),
       "play[0].action[0].when_gap_below_m", "got 0"},
      {"negative ttc condition",
       play(kRole + "  action { role: \"a\" when_ttc_below_s: -2 speed { speed_kph: 0 } }\n"),
       "play[0].action[0].when_ttc_below_s", "got -2"},
      {"action without kind", play(kRole + "  action { role: \"a\" at_s: 1 }\n"), "play[0].action[0].kind",
       "speed, lane_change or indicator"},
      {"speed action without target", play(kRole + "  action { role: \"a\" speed { rate_mps2: 2 } }\n"),
       "play[0].action[0].speed.target", "required"},
      {"speed action too fast", play(kRole + "  action { role: \"a\" speed { speed_kph: 260 } }\n"),
       "play[0].action[0].speed.speed_kph", "got 260"},
      {"zero rate", play(kRole + "  action { role: \"a\" speed { speed_kph: 0 rate_mps2: 0 } }\n"),
       "play[0].action[0].speed.rate_mps2", "(0, 10] (got 0)"},
      {"harsh rate", play(kRole + "  action { role: \"a\" speed { speed_kph: 0 rate_mps2: 12 } }\n"),
       "play[0].action[0].speed.rate_mps2", "got 12"},
      {"lane change without offset", play(kRole + "  action { role: \"a\" lane_change { polite: true } }\n"),
       "play[0].action[0].lane_change.lane_offset", "required"},
      {"lane change by 0", play(kRole + "  action { role: \"a\" lane_change { lane_offset: 0 } }\n"),
       "play[0].action[0].lane_change.lane_offset", "must be -2, -1, 1 or 2 (got 0)"},
      {"lane change by 3", play(kRole + "  action { role: \"a\" lane_change { lane_offset: 3 } }\n"),
       "play[0].action[0].lane_change.lane_offset", "got 3"},
      {"lane change off the road",
       play("  role { name: \"a\" lane_offset: 1 ahead_m: 50 speed_kph: 80 }\n"
            "  action { role: \"a\" lane_change { lane_offset: -1 } }\n"
            "  action { role: \"a\" lane_change { lane_offset: -1 } }\n"),
       "play[0].action[1].lane_change.lane_offset", "takes role \"a\" to lane -1 relative to the ego's"},
      {"lane change beyond the other roles' lanes",
       play("  role { name: \"a\" lane_offset: 1 ahead_m: 50 speed_kph: 80 }\n"
            "  role { name: \"b\" ahead_m: 80 speed_kph: 80 }\n"
            "  action { role: \"b\" lane_change { lane_offset: -1 } }\n"),
       "play[0].action[0].lane_change.lane_offset", "run from -1 to 1: 3 lanes, but the road has 2"},
      {"roles on both sides of the ego on a two-lane road",
       play("  role { name: \"a\" lane_offset: 1 ahead_m: 50 speed_kph: 80 }\n"
            "  role { name: \"b\" lane_offset: -1 ahead_m: 50 speed_kph: 80 }\n"),
       "play[0].role[1].lane_offset", "run from -1 to 1: 3 lanes"},
      {"a clear zone on the other side of the ego from a role",
       play("  role { name: \"a\" lane_offset: 1 ahead_m: 50 speed_kph: 80 }\n"
            "  clear { lane_offset: -1 from_m: 0 to_m: 50 }\n"),
       "play[0].clear[0].lane_offset", "3 lanes"},
      {"oncoming lane change off the road",
       play("  role { name: \"a\" direction: BACKWARD ahead_m: 50 speed_kph: 80 }\n"
            "  action { role: \"a\" lane_change { lane_offset: -1 } }\n"),
       "play[0].action[0].lane_change.lane_offset", "oncoming lane -1, which does not exist"},
      {"short lane change", play(kRole + "  action { role: \"a\" lane_change { lane_offset: 1 duration_s: 0.5 } }\n"),
       "play[0].action[0].lane_change.duration_s", "[1, 10] (got 0.5)"},
      {"indicator without side", play(kRole + "  action { role: \"a\" indicator { } }\n"),
       "play[0].action[0].indicator.side", "required: OFF, LEFT or RIGHT"},
      {"empty clear zone", play(kRole + "  clear { from_m: 50 to_m: 20 }\n"), "play[0].clear[0].to_m",
       "greater than from_m"},
      {"clear zone without from_m", play(kRole + "  clear { to_m: 20 }\n"), "play[0].clear[0].from_m", "required"},
      {"clear zone beyond the road", play(kRole + "  clear { lane_offset: -2 from_m: 0 to_m: 20 }\n"),
       "play[0].clear[0].lane_offset", "[-1, 1] (got -2)"},
      {"clear zone outside the inner region", play(kRole + "  clear { from_m: -300 to_m: 20 }\n"),
       "play[0].clear[0].from_m", "inner region"},
      {"zero end", play(kRole + "  end { after_s: 0 }\n"), "play[0].end.after_s", "(0, 600] (got 0)"},
      {"endless play", play(kRole + "  end { after_s: 900 }\n"), "play[0].end.after_s", "got 900"},
      {"end before the handover", play(kRole + "  end { ego_beyond_s_m: 2500 }\n"), "play[0].end.ego_beyond_s_m",
       "beyond trigger2_s_m"},
      {"end off the road", play(kRole + "  end { ego_beyond_s_m: 20000 }\n"), "play[0].end.ego_beyond_s_m",
       "got 20000"},
      {"long release", play(kRole + "  release_s: 100\n"), "play[0].release_s", "[0, 60] (got 100)"},
      {"negative release", play(kRole + "  release_s: -1\n"), "play[0].release_s", "got -1"},
      {"long handover wait", play(kRole + "  handover_wait_s: 30\n"), "play[0].handover_wait_s", "[0, 20] (got 30)"},
      {"negative handover wait", play(kRole + "  handover_wait_s: -1\n"), "play[0].handover_wait_s", "got -1"},
      {"no acceleration memory", "director { accel_memory_s: 0 }\n", "director.accel_memory_s", "got 0"},
      {"zero speed offset", "director { max_speed_offset_kph: 0 }\n", "director.max_speed_offset_kph", "got 0"},
      {"negative minimum speed", "director { min_speed_kph: -5 }\n", "director.min_speed_kph", "got -5"},
      {"hasty transport", "director { transport_rate_mps2: 4 }\n", "director.transport_rate_mps2", "(got 4)"},
      {"zero jerk", "director { max_jerk_mps3: 0 }\n", "director.max_jerk_mps3", "(0, 20] (got 0)"},
      {"harsh jerk", "director { max_jerk_mps3: 25 }\n", "director.max_jerk_mps3", "got 25"},
      {"free lane changes", "director { lane_change_cost_kph: 0 }\n", "director.lane_change_cost_kph", "got 0"},
      {"no hidden margin", "director { hidden_margin_m: 0 }\n", "director.hidden_margin_m", "got 0"},
      {"no approach", "director { beside_approach_s: 0 }\n", "director.beside_approach_s", "got 0"},
      {"waiting out of the window", "director { beside_wait_ahead_m: 2000 }\n", "director.beside_wait_ahead_m",
       "got 2000"},
      {"a negative oncoming gap", "director { oncoming_gap_m: -100 }\n", "director.oncoming_gap_m", "got -100"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const Loaded l = load_text(scenario_with(c.text, c.road), "bad.pbtxt");
    EXPECT_FALSE(l.ok());
    EXPECT_TRUE(has_problem(l, c.field, c.reason)) << "expected " << c.field << ": ..." << c.reason << "...\n"
                                                   << all(l);
  }
}

// A transparent ego (a probe the traffic drives through) is for validating the window; a play is
// staged around an ego the traffic sees, so the two are refused together.
TEST(ScenarioPlays, ATransparentEgoIsAcceptedWithoutPlaysAndRefusedWithThem) {
  const auto transparent = [](const std::string& text) {
    std::string t = text;
    const std::string ego = "ego { start_s_m: 1000";
    t.replace(t.find(ego), ego.size(), "ego { transparent: true start_s_m: 1000");
    return t;
  };
  const Loaded alone = load_text(transparent(scenario_with("")), "probe.pbtxt");
  ASSERT_TRUE(alone.ok()) << all(alone);
  EXPECT_TRUE(alone.config.ego.transparent);
  EXPECT_FALSE(load_text(scenario_with(""), "ego.pbtxt").config.ego.transparent);
  const Loaded with_play = load_text(transparent(scenario_with(play(kRole))), "probe_play.pbtxt");
  EXPECT_TRUE(has_problem(with_play, "ego.transparent", "cannot have plays")) << all(with_play);
}

TEST(ScenarioPlays, AValidPlayRaisesNoFollowOnProblems) {
  // An oncoming role's lane changes within the oncoming lanes, forward roles' within the lanes of
  // the ego's direction, a role just far enough from the ego in its lane, slots in other lanes.
  const Loaded l = load_text(
      scenario_with(play("  role { name: \"a\" direction: BACKWARD ahead_m: 100 speed_kph: 80 }\n"
                         "  role { name: \"b\" lane_offset: 1 ahead_m: 0 speed_offset_kph: 5 }\n"
                         "  role { name: \"c\" lane_offset: 1 ahead_m: 30 speed_offset_kph: 5 }\n"
                         "  role { name: \"d\" ahead_m: -8 speed_kph: 100 }\n"
                         "  action { role: \"a\" lane_change { lane_offset: 1 } }\n"
                         "  action { role: \"a\" lane_change { lane_offset: -1 } }\n"
                         "  action { role: \"b\" lane_change { lane_offset: -1 } }\n"
                         "  action { role: \"b\" lane_change { lane_offset: 1 } }\n"
                         "  action { role: \"c\" at_s: 3 lane_change { lane_offset: -1 } }\n"
                         "  clear { lane_offset: 1 from_m: -20 to_m: 40 }\n")),
      "ok.pbtxt");
  EXPECT_TRUE(l.ok()) << all(l);
}

}  // namespace
}  // namespace entourage::scenario
