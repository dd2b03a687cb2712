// Fault injection: every service drops a tenth of the DDS data messages it sends (UDP only, no
// shared memory; ENTOURAGE_FAULT_DROP_PERCENT, common/dds/node.cpp). Reliability must repair every
// loss, so that every handoff is applied exactly once and the lockstep run records exactly what
// the same run records without losses: the exported vehicles, ego and handoffs are identical, byte
// for byte, and every invariant holds.
#include <gtest/gtest.h>

#include <string>

#include "process_util.hpp"
#include "../test_domains.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomainLossy = test_domain::kFaultLossy;
constexpr int kDomainClean = test_domain::kFaultClean;
constexpr int kDomainLossyCarried = test_domain::kFaultLossyCarried;
constexpr int kDomainCleanCarried = test_domain::kFaultCleanCarried;

std::string run_and_export(const std::string& dir, const std::string& env, int domain, const std::string& extra = "") {
  const std::string rec = dir + "/r.mcap";
  const CommandResult r = run_command(env + bin("entourage") + " run " + source("scenarios/freeway.pbtxt") +
                                      " --lockstep --seed 7 --duration 20 --quiet --domain " + std::to_string(domain) +
                                      " --record " + rec + extra);
  EXPECT_EQ(r.exit_code, 0) << r.output;  // exit 0: every invariant held
  EXPECT_TRUE(no_process_uses_domain(domain));
  const CommandResult e = run_command(bin("entourage") + " export " + rec + " --csv " + dir + "/csv");
  EXPECT_EQ(e.exit_code, 0) << e.output;
  return dir + "/csv/";
}

// The exports of two runs hold the same vehicles, ego and handoffs, byte for byte.
void expect_same_rows(const std::string& lossy, const std::string& clean) {
  for (const char* file : {"vehicles.csv", "ego.csv", "handoffs.csv"}) {
    const std::string a = file_bytes(lossy + file);
    const std::string b = file_bytes(clean + file);
    EXPECT_GT(b.size(), 100U) << file;
    EXPECT_TRUE(a == b) << file << " differs between the lossy and the clean run";
  }
}

TEST(Faults, ATenthOfTheDataMessagesLostChangesNothingInTheRecording) {
  const std::string lossy = run_and_export(fresh_dir("lossy"), "ENTOURAGE_FAULT_DROP_PERCENT=10 ", kDomainLossy);
  expect_same_rows(lossy, run_and_export(fresh_dir("clean"), "", kDomainClean));
}

// Meso writing only the states its readers cannot carry forward (--meso-states carried): a lost
// sample that a reader got late would leave its rebuilt vehicles wrong; reliability and the step's
// counts must deliver every one before the step is taken.
TEST(Faults, ATenthOfTheDataMessagesLostChangesNothingWhenReadersCarryMesoStatesForward) {
  const std::string lossy =
      run_and_export(fresh_dir("lossy-carried"), "ENTOURAGE_FAULT_DROP_PERCENT=10 ", kDomainLossyCarried,
                     " --meso-states carried");
  expect_same_rows(lossy, run_and_export(fresh_dir("clean-every"), "", kDomainCleanCarried));
}

TEST(Faults, AMalformedDropPercentageIsRefusedAtStartup) {
  const CommandResult r = run_command("ENTOURAGE_FAULT_DROP_PERCENT=lots " + bin("entourage-micro") + " --domain " +
                                      std::to_string(kDomainLossy) + " --scenario " + source("scenarios/freeway.pbtxt"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("ENTOURAGE_FAULT_DROP_PERCENT"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace entourage::testing
