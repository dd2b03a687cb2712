// Scenario loading: defaults, unit conversions, and every problem named with file, line and field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scenario/loader.hpp"

namespace entourage::scenario {
namespace {

const std::string kDir = std::string(ENTOURAGE_SOURCE_DIR) + "/tests/scenarios/";

bool has_problem(const Loaded& l, int line, const std::string& field, const std::string& text) {
  for (const auto& p : l.problems) {
    if (p.line == line && p.field == field && p.message.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string all(const Loaded& l) {
  std::string s;
  for (const auto& p : l.problems) s += p.to_string() + "\n";
  return s;
}

TEST(Scenario, ShippedScenariosAreValid) {
  std::vector<std::string> files{std::string(ENTOURAGE_SOURCE_DIR) + "/tests/scenarios/minimal.pbtxt"};
  for (const auto& e : std::filesystem::directory_iterator(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios")) {
    if (e.path().extension() == ".pbtxt") files.push_back(e.path().string());
  }
  EXPECT_GE(files.size(), 6U);
  for (const auto& f : files) {
    const Loaded l = load_file(f);
    EXPECT_TRUE(l.ok()) << f << "\n" << all(l);
  }
}

TEST(Scenario, DefaultsAndUnitsAreResolved) {
  const Loaded l = load_file(kDir + "minimal.pbtxt");
  ASSERT_TRUE(l.ok()) << all(l);
  const ScenarioConfig& c = l.config;
  EXPECT_DOUBLE_EQ(c.step_s, 0.1);
  EXPECT_EQ(c.steps(), 600U);
  EXPECT_NEAR(c.road.speed_limit_mps, 120.0 / 3.6, 1e-12);
  EXPECT_DOUBLE_EQ(c.road.lane_width_m, 3.5);
  EXPECT_DOUBLE_EQ(c.window.inner_ahead_m, 400.0);
  EXPECT_NEAR(c.forward.flow_veh_per_s, 1200.0 / 3600.0, 1e-12);
  ASSERT_EQ(c.forward.type_shares.size(), 1U);
  EXPECT_DOUBLE_EQ(c.forward.type_shares[0], 1.0);
  const DriverPopulation& d = c.vehicle_types[0].driver;
  EXPECT_NEAR(d.desired_speed_mps.mean, 115.0 / 3.6, 1e-12);
  EXPECT_NEAR(d.desired_speed_mps.max, 150.0 / 3.6, 1e-12);
  EXPECT_DOUBLE_EQ(d.time_gap_s.mean, 1.5);  // default
  EXPECT_DOUBLE_EQ(d.time_gap_s.sd, 0.0);
  EXPECT_DOUBLE_EQ(d.beta, 1.35);
  EXPECT_NEAR(c.ego.driver.desired_speed_mps, 110.0 / 3.6, 1e-12);
  // An overtaker cutting back in asks a follower no more than the weakest brakes of the types.
  EXPECT_DOUBLE_EQ(c.overtaking.follower_max_decel_mps2, c.vehicle_types[0].max_decel_mps2);
  const Loaded rural = load_file(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/rural_slow_truck.pbtxt");
  ASSERT_TRUE(rural.ok()) << all(rural);
  EXPECT_DOUBLE_EQ(rural.config.overtaking.follower_max_decel_mps2, 6.0);  // the trucks'
}

TEST(Scenario, SyntaxErrorNamesTheLine) {
  const Loaded l = load_file(kDir + "bad_syntax.pbtxt");
  EXPECT_FALSE(l.ok());
  ASSERT_FALSE(l.problems.empty());
  EXPECT_EQ(l.problems[0].line, 10) << all(l);
  EXPECT_NE(l.problems[0].message.find("vehicle_type"), std::string::npos) << all(l);
}

TEST(Scenario, NegativeFlowIsRefused) {
  const Loaded l = load_file(kDir + "bad_negative_flow.pbtxt");
  EXPECT_FALSE(l.ok());
  EXPECT_TRUE(has_problem(l, 18, "demand.forward.flow_veh_per_h", "-1200")) << all(l);
}

TEST(Scenario, ZeroLanesAreRefused) {
  const Loaded l = load_file(kDir + "bad_zero_lanes.pbtxt");
  EXPECT_FALSE(l.ok());
  EXPECT_TRUE(has_problem(l, 6, "road.lanes_forward", "got 0")) << all(l);
}

TEST(Scenario, UnknownModelIsRefused) {
  const Loaded l = load_file(kDir + "bad_unknown_model.pbtxt");
  EXPECT_FALSE(l.ok());
  EXPECT_TRUE(has_problem(l, 13, "vehicle_type[0].driver.car_following", "\"idn\"")) << all(l);
}

// The ACC model's coolness: below 1, only with idm or modified_idm and without the HDM; resolved
// for a type's drivers and for the ego.
TEST(Scenario, CoolnessIsCheckedAndResolved) {
  const auto minimal_with = [](const std::string& from, const std::string& to) {
    std::ifstream in(kDir + "minimal.pbtxt");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return load_text(text.replace(at, from.size(), to), "minimal.pbtxt");
  };
  const Loaded good = minimal_with("car_following: \"idm\"", "car_following: \"idm\" coolness: 0.99");
  ASSERT_TRUE(good.ok()) << all(good);
  EXPECT_DOUBLE_EQ(good.config.vehicle_types[0].driver.coolness, 0.99);
  const Loaded ego = minimal_with("idm { desired_speed_kph: 110 }", "idm { desired_speed_kph: 110 coolness: 0.5 }");
  ASSERT_TRUE(ego.ok()) << all(ego);
  EXPECT_DOUBLE_EQ(ego.config.ego.driver.coolness, 0.5);
  const Loaded one = minimal_with("car_following: \"idm\"", "car_following: \"idm\" coolness: 1");
  EXPECT_TRUE(has_problem(one, 13, "vehicle_type[0].driver.coolness", "[0, 0.999]")) << all(one);
  const Loaded gipps = minimal_with("car_following: \"idm\"", "car_following: \"gipps\" coolness: 0.9");
  EXPECT_TRUE(has_problem(gipps, 13, "vehicle_type[0].driver.coolness", "not gipps")) << all(gipps);
  const Loaded hdm =
      minimal_with("car_following: \"idm\"", "car_following: \"idm\" coolness: 0.9 human_driver { }");
  EXPECT_TRUE(has_problem(hdm, 13, "vehicle_type[0].driver.coolness", "human_driver")) << all(hdm);
  const Loaded bad_ego = minimal_with("idm { desired_speed_kph: 110 }", "idm { desired_speed_kph: 110 coolness: -1 }");
  EXPECT_TRUE(has_problem(bad_ego, 23, "ego.idm.coolness", "got -1")) << all(bad_ego);
}

TEST(Scenario, MissingFileIsReported) {
  const Loaded l = load_file(kDir + "no_such_file.pbtxt");
  ASSERT_EQ(l.problems.size(), 1U);
  EXPECT_NE(l.problems[0].to_string().find("cannot open"), std::string::npos);
}

TEST(Scenario, EveryProblemIsReportedNotJustTheFirst) {
  const std::string text = R"(name: "many"
road { length_m: 5000 lanes_forward: 9 speed_limit_kph: -5 }
vehicle_type { name: "car" driver { desired_speed_kph { mean: 100 } politeness { mean: 3 } } }
vehicle_type { name: "car" driver { desired_speed_kph { mean: 100 } } }
demand { forward { flow_veh_per_h: 100 mix { type: "bus" share: 1 } } }
play { name: "p" trigger1_s_m: 900 trigger2_s_m: 800 }
)";
  const Loaded l = load_text(text, "inline.pbtxt");
  EXPECT_TRUE(has_problem(l, 2, "road.lanes_forward", "got 9")) << all(l);
  EXPECT_TRUE(has_problem(l, 2, "road.speed_limit_kph", "got -5")) << all(l);
  EXPECT_TRUE(has_problem(l, 3, "vehicle_type[0].driver.politeness.mean", "got 3")) << all(l);
  EXPECT_TRUE(has_problem(l, 4, "vehicle_type[1].name", "defined twice")) << all(l);
  EXPECT_TRUE(has_problem(l, 5, "demand.forward.mix[0].type", "\"bus\"")) << all(l);
  EXPECT_TRUE(has_problem(l, 6, "play[0].trigger2_s_m", "beyond trigger1")) << all(l);
  EXPECT_TRUE(has_problem(l, 2, "road.length_m", "too short")) << all(l);
}

TEST(Scenario, MissingRequiredPartsPointAtTheEnclosingMessage) {
  const Loaded l = load_text("name: \"x\"\nroad {\n  lanes_forward: 1\n}\n", "inline.pbtxt");
  EXPECT_TRUE(has_problem(l, 2, "road.length_m", "required")) << all(l);
  EXPECT_TRUE(has_problem(l, 2, "road.speed_limit_kph", "required")) << all(l);
  EXPECT_TRUE(has_problem(l, 1, "demand", "required")) << all(l);
}

}  // namespace
}  // namespace entourage::scenario
