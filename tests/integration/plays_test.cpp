// A shipped play end to end, every service a process over DDS in lockstep: the director casts an
// actor, moves it into place, hands it over at trigger point 2, runs the script and releases it;
// its commands and the play's progress are in the recording, the actor shows as controlled in the
// vehicle states, and every invariant of the window holds with the director at work.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "process_util.hpp"
#include "../test_domains.hpp"
#include "recorded_run.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomain = test_domain::kPlays;

TEST(Plays, TheLeadVehicleBrakesPlayRunsEndToEndOverDds) {
  const std::string dir = fresh_dir("plays");
  const std::string scenario_path = source("scenarios/freeway_lead_brakes.pbtxt");
  const CommandResult r = run_command(bin("entourage") + " run " + scenario_path + " --seed 2 --lockstep --quiet --domain " +
                                      std::to_string(kDomain) + " --record " + dir + "/r.mcap");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(no_process_uses_domain(kDomain));

  RecordedRun run;
  ASSERT_NO_FATAL_FAILURE(read_run(scenario_path, dir + "/r.mcap", &run));
  expect_invariants(run);

  std::set<std::uint32_t> phases;
  std::string failure;
  for (const auto& p : run.tables.plays) {
    phases.insert(p.phase);
    if (p.phase == 7) failure = p.detail;
  }
  for (std::uint32_t phase : {1U, 2U, 3U, 4U, 5U, 6U}) {
    EXPECT_EQ(phases.count(phase), 1U) << "phase " << phase << " reported; failure: " << failure;
  }
  EXPECT_EQ(phases.count(7U), 0U) << failure;

  // The actor was transported, then controlled, then released, and the commands say so too.
  std::set<std::string> controls;
  for (const auto& v : run.tables.vehicles) controls.insert(v.control);
  for (const char* c : {"transported", "controlled", "releasing"}) EXPECT_EQ(controls.count(c), 1U) << c;
  std::set<std::string> modes;
  for (const auto& c : run.tables.commands) modes.insert(c.mode);
  for (const char* m : {"transported", "controlled", "releasing", "autonomous"}) EXPECT_EQ(modes.count(m), 1U) << m;
  std::filesystem::remove_all(dir);
}

// Three plays in one drive over DDS (freeway_three_plays.pbtxt): each is done in turn, and at the
// end no vehicle is under the director's control, also those released after they had left the
// window ahead (the generator now reads the director's commands for its front zone).
TEST(Plays, ThreePlaysInOneDriveAreEachDoneAndLeaveNoVehicleUnderCommandOverDds) {
  const std::string dir = fresh_dir("three_plays");
  const std::string scenario_path = source("scenarios/freeway_three_plays.pbtxt");
  const int domain = test_domain::kSeveralPlays;
  // The scenario's 600 s: the last play ends with some 100 s to spare.
  const CommandResult r = run_command(bin("entourage") + " run " + scenario_path +
                                      " --seed 3 --lockstep --quiet --domain " + std::to_string(domain) +
                                      " --record " + dir + "/r.mcap");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(no_process_uses_domain(domain));

  RecordedRun run;
  ASSERT_NO_FATAL_FAILURE(read_run(scenario_path, dir + "/r.mcap", &run));
  expect_invariants(run);
  std::map<std::uint32_t, std::uint32_t> last_phase;  // per play id
  for (const auto& p : run.tables.plays) last_phase[p.play_id] = p.phase;
  ASSERT_EQ(last_phase.size(), 3U);
  for (const auto& [id, phase] : last_phase) EXPECT_EQ(phase, 6U) << "play " << id;
  std::uint64_t last_step = 0;
  for (const auto& v : run.tables.vehicles) last_step = std::max(last_step, v.step);
  for (const auto& v : run.tables.vehicles) {
    if (v.step == last_step) {
      EXPECT_EQ(v.control, "autonomous") << "vehicle " << v.id;
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace entourage::testing
