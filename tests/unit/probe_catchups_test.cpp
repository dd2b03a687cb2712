// A transparent probe's catch-ups in drives of the window (every core in one process) against the
// moving-observer prediction. A probe is the observer the relations are made for (scenario
// ego.transparent: nobody sees it, it sees nobody), so these test the window's stream itself: the
// generation at the edges, meso, the transitions. 48 drives per speed give 1.04 and 1.10 on the
// rural road (stop 40's prediction: passers counted, only where the window is on a stretch like the
// reference road) and 0.94 on the freeway at 130 km/h (services/generator/README.md, *Catch-ups of a
// transparent probe*); these shorter runs (fixed seeds) must come within 15 %: a guard against a
// gross error in the stream, not a measure (the generator's queue defect of stop 24, which cost
// a slow freeway probe a tenth of its passive catch-ups, passed them: its own test is in
// generator_test.cpp). The freeway's slow probe, 0.90 with 48 drives since stop 25's front zone
// (0.81 before; 0.86 on this test's 8 drives, a hair inside the bound), is tested here too; the freeway
// probe at the stream's speed has no test here: 0.99 / 0.93 with 48 drives since stop 27 (0.92 /
// 0.84 before), but a drive's active catch-ups there range from a tenth to 1.3 times the
// prediction, and seeds 1-12 give 0.81.
#include <gtest/gtest.h>

#include <string>

#include "core_test_util.hpp"
#include "window_catchups.hpp"

namespace entourage::bench {
namespace {

ScenarioConfig shipped(const std::string& name) { return testing::shipped_scenario(name); }

// Seeds 1..drives, 20 minutes each, summed.
Tally probe_drives(const std::string& scenario, double speed_kph, int drives) {
  const ScenarioConfig sc = with_probe(shipped(scenario), speed_kph);
  Tally total;
  for (int seed = 1; seed <= drives; ++seed) total.add(window_drive(sc, static_cast<std::uint64_t>(seed), 1200.0));
  return total;
}

constexpr double kShortRunTolerance = 0.15;

// Catch-ups counted against their prediction, within the tolerance, once more than
// `enough_predicted` are predicted.
void expect_as_predicted(double observed, double predicted, double enough_predicted) {
  ASSERT_GT(predicted, enough_predicted);
  EXPECT_NEAR(observed / predicted, 1.0, kShortRunTolerance) << observed << " of " << predicted;
}

TEST(ProbeCatchUps, OnTheRuralRoadASlowProbeIsPassedAsOftenAsPredicted) {
  const Tally t = probe_drives("rural", 70.0, 16);
  expect_as_predicted(t.passive, t.predicted_passive, 200.0);
}

TEST(ProbeCatchUps, OnTheRuralRoadAFastProbePassesAsManyAsPredicted) {
  const Tally t = probe_drives("rural", 100.0, 16);
  expect_as_predicted(t.active, t.predicted_active, 400.0);
}

TEST(ProbeCatchUps, OnTheFreewayASlowProbeIsPassedAsOftenAsPredicted) {
  const Tally t = probe_drives("freeway", 80.0, 8);
  expect_as_predicted(t.passive, t.predicted_passive, 800.0);
}

TEST(ProbeCatchUps, OnTheFreewayAFastProbePassesAsManyAsPredicted) {
  const Tally t = probe_drives("freeway", 130.0, 12);
  expect_as_predicted(t.active, t.predicted_active, 1000.0);
}

}  // namespace
}  // namespace entourage::bench
