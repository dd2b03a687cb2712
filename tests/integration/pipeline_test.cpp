// The whole pipeline: every service a real process over DDS, driven by `entourage run` in
// lockstep, checked from the exported recording; identical seeds give identical recordings.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include "process_util.hpp"
#include "../test_domains.hpp"
#include "recording/checks.hpp"
#include "recording/recording.hpp"
#include "recording/csv_tables.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomainLockstep = test_domain::kPipelineLockstep;
constexpr int kDomainSplit = test_domain::kPipelineSplit;
constexpr int kDomainRealtime = test_domain::kPipelineRealtime;
constexpr int kDomainCarried = test_domain::kPipelineCarried;

std::string run_scenario(const std::string& dir, const std::string& name, int domain, const std::string& extra) {
  return bin("entourage") + " run " + source("scenarios/freeway.pbtxt") + " --quiet --domain " +
         std::to_string(domain) + " --record " + dir + "/" + name + ".mcap " + extra;
}

void expect_invariants(const std::string& csv_dir) {
  std::string error;
  const auto t = recording::read_csv(csv_dir, &error);
  ASSERT_TRUE(t) << error;
  EXPECT_GT(t->vehicles.size(), 10000U);
  for (const auto& c : recording::check_invariants(*t, EgoConfig{})) {
    EXPECT_TRUE(c.passed) << c.name << ": " << c.detail;
  }
}

// The summary's CPU time per step of each service's process, and the vehicle states micro and meso
// wrote per step (the default freeway: some 20 in micro, 30 in meso).
// The run summary's CPU line: a figure for every service, and the states micro and meso wrote per
// step (meso, whose states its readers carry forward by default in lockstep, far fewer than micro).
void expect_cpu_per_step(const std::string& output) {
  std::map<std::string, double> written;
  for (const char* service : {"ego", "generator", "micro", "meso", "director", "recorder"}) {
    const std::regex figure(std::string("[:,] ") + service + R"( ([0-9.]+) us( \(([0-9.]+)\))?)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(output, m, figure)) << service << " has no CPU figure in:\n" << output;
    EXPECT_GT(std::stod(m[1].str()), 0.0) << service;
    const bool writes_states = std::string(service) == "micro" || std::string(service) == "meso";
    if (writes_states) {
      ASSERT_TRUE(m[3].matched) << service << " has no count of the states it wrote";
      written[service] = std::stod(m[3].str());
    }
  }
  EXPECT_GT(written["micro"], 5.0);
  EXPECT_GT(written["meso"], 0.5);
  EXPECT_LT(written["meso"], 0.5 * written["micro"]) << "meso's states are carried forward by default in lockstep";
}

TEST(Pipeline, LockstepRunHoldsTheInvariantsAndIsReproducible) {
  const std::string dir = fresh_dir("lockstep");
  for (const char* name : {"a", "b"}) {
    const CommandResult r = run_command(run_scenario(dir, name, kDomainLockstep, "--lockstep --seed 7 --duration 60"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("simulated 60.0 s (600 steps)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("meso writes only the states its readers cannot carry forward"), std::string::npos);
    expect_cpu_per_step(r.output);
    const CommandResult e =
        run_command(bin("entourage") + " export " + dir + "/" + name + ".mcap --csv " + dir + "/" + name);
    ASSERT_EQ(e.exit_code, 0) << e.output;
  }
  EXPECT_TRUE(no_process_uses_domain(kDomainLockstep));
  expect_invariants(dir + "/a");
  const std::string va = file_bytes(dir + "/a/vehicles.csv");
  EXPECT_GT(va.size(), 1000000U);
  EXPECT_EQ(va, file_bytes(dir + "/b/vehicles.csv")) << "same seed, different vehicles";
  EXPECT_EQ(file_bytes(dir + "/a/ego.csv"), file_bytes(dir + "/b/ego.csv"));
  EXPECT_EQ(file_bytes(dir + "/a/handoffs.csv"), file_bytes(dir + "/b/handoffs.csv"));
  EXPECT_EQ(file_bytes(dir + "/a.mcap"), file_bytes(dir + "/b.mcap")) << "recordings differ byte for byte";
  std::filesystem::remove_all(dir);
}

// Meso writing only the states its readers cannot carry forward (--meso-states carried,
// common/traffic/carried_states.hpp): every service sees the same world, bit for bit, so the run and
// its recording's rows are those of a run where meso writes every state; its two processes write
// a small share of them.
TEST(Pipeline, MesoWritingOnlyStatesItsReadersCannotCarryForwardLeavesTheRunBitForBitTheSame) {
  const std::string dir = fresh_dir("carried");
  for (const char* name : {"every", "carried"}) {
    const std::string states = std::string(" --meso-states ") + name;
    const CommandResult r =
        run_command(run_scenario(dir, name, kDomainCarried, "--lockstep --meso split --seed 5 --duration 40" + states));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const CommandResult e =
        run_command(bin("entourage") + " export " + dir + "/" + name + ".mcap --csv " + dir + "/" + name);
    ASSERT_EQ(e.exit_code, 0) << e.output;
  }
  EXPECT_TRUE(no_process_uses_domain(kDomainCarried));
  for (const char* table : {"vehicles.csv", "ego.csv", "handoffs.csv", "commands.csv"}) {
    EXPECT_EQ(file_bytes(dir + "/every/" + table), file_bytes(dir + "/carried/" + table)) << table << " differs";
  }
  std::string error;
  const auto rec = recording::read_recording(dir + "/carried.mcap", &error);
  ASSERT_TRUE(rec) << error;
  std::uint64_t written = 0;
  bool carried = false;
  for (const auto& d : rec->done) {
    if (ServiceId::from_code(d.service()).role != Role::kMeso) continue;
    written += d.vehicle_states();
    carried = carried || d.carried_states();
  }
  EXPECT_TRUE(carried);
  std::uint64_t rows = 0;
  for (const auto& m : rec->vehicles) rows += ServiceId::from_code(m.owner()).role == Role::kMeso ? 1 : 0;
  EXPECT_GT(rows, 10000U);
  EXPECT_LT(written, rows / 4) << "meso wrote " << written << " of its " << rows << " states";
  // Real time refuses it: a reader there may miss a step.
  const CommandResult rt = run_command(run_scenario(dir, "rt", kDomainCarried, "--realtime --meso-states carried"));
  EXPECT_EQ(rt.exit_code, 2) << rt.output;
  EXPECT_NE(rt.output.find("needs lockstep"), std::string::npos) << rt.output;
  std::filesystem::remove_all(dir);
}

TEST(Pipeline, TwoMesoProcessesServeTheOuterRegionsAndPlaysAreFollowed) {
  const std::string dir = fresh_dir("split");
  const CommandResult r = run_command(bin("entourage") + " run " + source("tests/scenarios/with_play.pbtxt") +
                                      " --quiet --meso split --seed 3 --duration 36 --domain " +
                                      std::to_string(kDomainSplit) + " --record " + dir + "/s.mcap");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("meso-front, meso-rear"), std::string::npos) << r.output;
  ASSERT_EQ(run_command(bin("entourage") + " export " + dir + "/s.mcap --csv " + dir + "/s").exit_code, 0);
  std::string error;
  const auto t = recording::read_csv(dir + "/s", &error);
  ASSERT_TRUE(t) << error;
  bool front = false;
  bool rear = false;
  for (const auto& v : t->vehicles) {
    front = front || v.owner == "meso-front";
    rear = rear || v.owner == "meso-rear";
    EXPECT_NE(v.owner, "meso");
  }
  EXPECT_TRUE(front && rear);
  for (const auto& c : recording::check_invariants(*t, EgoConfig{})) EXPECT_TRUE(c.passed) << c.name << ": " << c.detail;
  // the director reported the play waiting, then preparing at trigger point 1 (1300 m; the ego
  // starts at 1000 m at 110 km/h), then the outcome at trigger point 2 (1700 m, at about 23 s) or
  // at the end of the handover's wait (6 s): handed over or failed
  const std::string plays = file_bytes(dir + "/s/plays.csv");
  EXPECT_NE(plays.find("lead vehicle brakes,0,"), std::string::npos) << plays;
  EXPECT_NE(plays.find("lead vehicle brakes,1,"), std::string::npos) << plays;
  EXPECT_TRUE(plays.find("lead vehicle brakes,4,") != std::string::npos ||
              plays.find("lead vehicle brakes,7,") != std::string::npos)
      << plays;
  EXPECT_TRUE(no_process_uses_domain(kDomainSplit));
  std::filesystem::remove_all(dir);
}

TEST(Pipeline, RealtimeRunIsPacedAndReportsItsLatency) {
  const std::string dir = fresh_dir("realtime");
  const auto t0 = std::chrono::steady_clock::now();
  const CommandResult r = run_command(run_scenario(dir, "rt", kDomainRealtime, "--realtime --duration 5"));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GE(wall, 5.0) << "five simulated seconds took less than five seconds of wall time";
  EXPECT_NE(r.output.find("ego state to world state: median"), std::string::npos) << r.output;
  EXPECT_TRUE(no_process_uses_domain(kDomainRealtime));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace entourage::testing
