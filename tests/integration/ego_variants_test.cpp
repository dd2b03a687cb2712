// The moving window around egos that do what a test person may do: stop in the lane for a minute,
// drive at 180 km/h, keep well below the stream's speed (the shipped scenarios
// freeway_ego_stops, freeway_ego_fast, freeway_ego_slow), and on the rural road drive below the
// stream or above it, overtaking in the oncoming lane (rural_ego_slow, rural_ego_fast), each end
// to end with every service a process over DDS. Every invariant holds (no vehicle appears or disappears in the inner region,
// none overlaps another), and the ego really did what the scenario says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "process_util.hpp"
#include "../test_domains.hpp"
#include "recorded_run.hpp"

namespace entourage::testing {
namespace {

struct Variant {
  std::string scenario;
  int domain;
  // What the run must show of the ego.
  std::function<void(const recording::Tables&)> ego_check;
};

void PrintTo(const Variant& v, std::ostream* os) { *os << v.scenario; }

void stood_for_a_minute(const recording::Tables& t) {
  const auto& ego = t.ego;
  std::size_t standing = 0;
  for (const auto& e : ego) standing += e.speed_mps == 0.0 ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(standing) * 0.1, 60.0, 0.5);
  EXPECT_GT(ego.back().speed_mps, 5.0) << "it drove on";
}

void mostly_near_180(const recording::Tables& t) {
  const auto& ego = t.ego;
  std::size_t fast = 0;
  for (const auto& e : ego) fast += e.speed_mps > 170.0 / 3.6 ? 1 : 0;
  EXPECT_GT(static_cast<double>(fast) / static_cast<double>(ego.size()), 0.3);
}

double mean_kph(const std::vector<recording::EgoRow>& ego) {
  double sum = 0.0;
  for (const auto& e : ego) sum += e.speed_mps;
  return 3.6 * sum / static_cast<double>(ego.size());
}

void below_the_stream(const recording::Tables& t) { EXPECT_LT(mean_kph(t.ego), 85.0); }

// The rural stream's space-mean speed is about 80 km/h (the generator's log).
void below_the_rural_stream(const recording::Tables& t) { EXPECT_LT(mean_kph(t.ego), 70.0); }

void overtakes_on_the_rural_road(const recording::Tables& t) {
  const auto& ego = t.ego;
  EXPECT_GT(mean_kph(ego), 80.0);
  const bool in_the_oncoming_lane =
      std::any_of(ego.begin(), ego.end(), [](const recording::EgoRow& e) { return e.lane >= 1; });
  EXPECT_TRUE(in_the_oncoming_lane) << "it never overtook";
}

// A transparent probe keeps its set speed (in these five minutes, the first part of its profile:
// 80 km/h on the freeway, 70 on the rural road, slowing in its curve like everyone: 66.8 on
// average) and the traffic drives through its place: some vehicle of its direction, in its lane,
// overlaps it in some step.
void transparent_at(const recording::Tables& t, double kph, double slack_kph) {
  EXPECT_NEAR(mean_kph(t.ego), kph, slack_kph);
  std::size_t e = 0;
  bool driven_through = false;
  for (const auto& v : t.vehicles) {
    while (e + 1 < t.ego.size() && t.ego[e].step < v.step) ++e;
    const auto& ego = t.ego[e];
    if (ego.step != v.step || v.direction != 1 || v.lane != ego.lane) continue;
    driven_through = driven_through || std::abs(v.s_m - ego.s_m) < 0.5 * (v.length_m + ego.length_m);
  }
  EXPECT_TRUE(driven_through) << "no vehicle drove through the probe's place";
}
void transparent_at_80(const recording::Tables& t) { transparent_at(t, 80.0, 0.5); }
void transparent_at_70_slowing_for_the_curve(const recording::Tables& t) { transparent_at(t, 67.0, 1.0); }

class EgoVariant : public ::testing::TestWithParam<Variant> {};

TEST_P(EgoVariant, TheWindowKeepsEveryInvariant) {
  const Variant& v = GetParam();
  const std::string dir = fresh_dir(v.scenario);
  const std::string scenario_path = source("scenarios/" + v.scenario + ".pbtxt");
  const CommandResult r = run_command(bin("entourage") + " run " + scenario_path + " --lockstep --quiet --domain " +
                                      std::to_string(v.domain) + " --record " + dir + "/r.mcap");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(no_process_uses_domain(v.domain));

  RecordedRun run;
  ASSERT_NO_FATAL_FAILURE(read_run(scenario_path, dir + "/r.mcap", &run));
  ASSERT_EQ(run.tables.ego.size(), 3001U);
  expect_invariants(run);
  v.ego_check(run.tables);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, EgoVariant,
                         ::testing::Values(Variant{"freeway_ego_stops", test_domain::kEgoStops, stood_for_a_minute},
                                           Variant{"freeway_ego_fast", test_domain::kEgoFast, mostly_near_180},
                                           Variant{"freeway_ego_slow", test_domain::kEgoSlow, below_the_stream},
                                           Variant{"rural_ego_slow", test_domain::kRuralEgoSlow, below_the_rural_stream},
                                           Variant{"rural_ego_fast", test_domain::kRuralEgoFast, overtakes_on_the_rural_road},
                                           Variant{"freeway_probe", test_domain::kProbe, transparent_at_80},
                                           Variant{"rural_probe", test_domain::kRuralProbe, transparent_at_70_slowing_for_the_curve}),
                         [](const ::testing::TestParamInfo<Variant>& p) { return p.param.scenario; });

}  // namespace
}  // namespace entourage::testing
