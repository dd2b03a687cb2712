// The rural scenario end to end (every service a real process over DDS): vehicles overtake in the
// oncoming lane, nobody collides head-on or otherwise, and traffic slows for the curve with its
// lower limit. Ten minutes: over five, how many overtakings the window sees depends much on the
// platoon the ego happens to drive in (1 to 28 for seeds 1 to 4).
#include <gtest/gtest.h>

#include <filesystem>

#include "process_util.hpp"
#include "../test_domains.hpp"
#include "recorded_run.hpp"
#include "recording/summary.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomainRural = test_domain::kRural;

TEST(Rural, OvertakingsInTheOncomingLaneWithoutCollisionsAndSlowerInTheCurve) {
  const std::string dir = fresh_dir("rural");
  const std::string scenario_path = source("scenarios/rural.pbtxt");
  const CommandResult r = run_command(bin("entourage") + " run " + scenario_path + " --lockstep --duration 600 --quiet --domain " +
                                      std::to_string(kDomainRural) + " --record " + dir + "/r.mcap");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(no_process_uses_domain(kDomainRural));

  RecordedRun run;
  ASSERT_NO_FATAL_FAILURE(read_run(scenario_path, dir + "/r.mcap", &run));
  const auto& sc = run.scenario;
  const recording::Tables& t = run.tables;
  expect_invariants(run);
  const recording::Manoeuvres m = recording::count_manoeuvres(t, sc.config);
  EXPECT_GE(m.overtakings, 3U) << "too few overtakings in ten minutes of rural traffic";

  // Vehicles in the curve (70 km/h zone, 3850-4650 m) drive slower than on the straight before it.
  double in_curve = 0.0;
  double straight = 0.0;
  std::size_t n_curve = 0;
  std::size_t n_straight = 0;
  for (const auto& v : t.vehicles) {
    if (v.region == "outside") continue;
    if (v.s_m > 3950.0 && v.s_m < 4550.0) {
      in_curve += v.speed_mps;
      ++n_curve;
    } else if (v.s_m > 2000.0 && v.s_m < 3000.0) {
      straight += v.speed_mps;
      ++n_straight;
    }
  }
  ASSERT_GT(n_curve, 500U);
  ASSERT_GT(n_straight, 500U);
  EXPECT_LT(in_curve / n_curve, 72.0 / 3.6);
  EXPECT_GT(straight / n_straight, in_curve / n_curve + 2.0);
  for (const auto& e : t.ego) {
    if (e.s_m > 3950.0 && e.s_m < 4550.0) {
      EXPECT_LT(e.speed_mps, 72.0 / 3.6) << "the ego stand-in at " << e.s_m;
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace entourage::testing
