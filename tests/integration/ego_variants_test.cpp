// The moving window around egos that do what a test person may do: stop in the lane for a minute,
// drive at 180 km/h, keep well below the stream's speed (the shipped scenarios
// freeway_ego_stops, freeway_ego_fast, freeway_ego_slow), and on the rural road drive below the
// stream or above it, overtaking in the oncoming lane (rural_ego_slow, rural_ego_fast), each end
// to end with every service a process over DDS. Every invariant holds (no vehicle appears or disappears in the inner region,
// none overlaps another), and the ego really did what the scenario says.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "process_util.hpp"
#include "recorded_run.hpp"

namespace entourage::testing {
namespace {

struct Variant {
  std::string scenario;
  int domain;
  // What the ego's own samples must show.
  std::function<void(const std::vector<recording::EgoRow>&)> ego_check;
};

void PrintTo(const Variant& v, std::ostream* os) { *os << v.scenario; }

void stood_for_a_minute(const std::vector<recording::EgoRow>& ego) {
  std::size_t standing = 0;
  for (const auto& e : ego) standing += e.speed_mps == 0.0 ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(standing) * 0.1, 60.0, 0.5);
  EXPECT_GT(ego.back().speed_mps, 5.0) << "it drove on";
}

void mostly_near_180(const std::vector<recording::EgoRow>& ego) {
  std::size_t fast = 0;
  for (const auto& e : ego) fast += e.speed_mps > 170.0 / 3.6 ? 1 : 0;
  EXPECT_GT(static_cast<double>(fast) / static_cast<double>(ego.size()), 0.3);
}

double mean_kph(const std::vector<recording::EgoRow>& ego) {
  double sum = 0.0;
  for (const auto& e : ego) sum += e.speed_mps;
  return 3.6 * sum / static_cast<double>(ego.size());
}

void below_the_stream(const std::vector<recording::EgoRow>& ego) { EXPECT_LT(mean_kph(ego), 85.0); }

// The rural stream's space-mean speed is about 80 km/h (the generator's log).
void below_the_rural_stream(const std::vector<recording::EgoRow>& ego) { EXPECT_LT(mean_kph(ego), 70.0); }

void overtakes_on_the_rural_road(const std::vector<recording::EgoRow>& ego) {
  EXPECT_GT(mean_kph(ego), 80.0);
  const bool in_the_oncoming_lane =
      std::any_of(ego.begin(), ego.end(), [](const recording::EgoRow& e) { return e.lane >= 1; });
  EXPECT_TRUE(in_the_oncoming_lane) << "it never overtook";
}

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
  v.ego_check(run.tables.ego);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, EgoVariant,
                         ::testing::Values(Variant{"freeway_ego_stops", 140, stood_for_a_minute},
                                           Variant{"freeway_ego_fast", 141, mostly_near_180},
                                           Variant{"freeway_ego_slow", 142, below_the_stream},
                                           Variant{"rural_ego_slow", 147, below_the_rural_stream},
                                           Variant{"rural_ego_fast", 148, overtakes_on_the_rural_road}),
                         [](const ::testing::TestParamInfo<Variant>& p) { return p.param.scenario; });

}  // namespace
}  // namespace entourage::testing
