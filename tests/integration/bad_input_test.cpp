// Bad input is refused at startup with file, line and field named, and nothing is started.
#include <gtest/gtest.h>

#include <filesystem>

#include "process_util.hpp"
#include "../test_domains.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomainService = test_domain::kBadInputService;

struct BadCase {
  int domain;         // each case its own (they run in parallel and check for leftover processes)
  const char* file;
  const char* where;  // file:line the message must name
  const char* what;   // the field (or token) the message must name
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.file; }

class BadScenario : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScenario, RunRefusesItAndStartsNothing) {
  const BadCase c = GetParam();
  const std::string dir = fresh_dir(std::string("bad_") + c.file);
  const std::string path = source(std::string("tests/scenarios/") + c.file);
  const CommandResult r = run_command(bin("entourage") + " run " + path + " --domain " + std::to_string(c.domain) +
                                      " --record " + dir + "/x.mcap");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(c.where), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(c.what), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no service was started"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.logs")) << "logs were created: something started";
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.mcap"));
  EXPECT_TRUE(no_process_uses_domain(c.domain));
  std::filesystem::remove_all(dir);
}

TEST_P(BadScenario, CheckRefusesItToo) {
  const BadCase c = GetParam();
  const CommandResult r = run_command(bin("entourage") + " check " + source(std::string("tests/scenarios/") + c.file));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(c.where), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(c.what), std::string::npos) << r.output;
}

TEST_P(BadScenario, AServiceRefusesItAtStartup) {
  const BadCase c = GetParam();
  const CommandResult r = run_command(bin("entourage-micro") + " --domain " + std::to_string(kDomainService) + " --scenario " +
                                      source(std::string("tests/scenarios/") + c.file));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(c.where), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, BadScenario,
    ::testing::Values(BadCase{test_domain::kBadSyntax, "bad_syntax.pbtxt", "bad_syntax.pbtxt:10:", "vehicle_type"},
                      BadCase{test_domain::kBadNegativeFlow, "bad_negative_flow.pbtxt", "bad_negative_flow.pbtxt:18:",
                              "demand.forward.flow_veh_per_h"},
                      BadCase{test_domain::kBadZeroLanes, "bad_zero_lanes.pbtxt", "bad_zero_lanes.pbtxt:6:", "road.lanes_forward"},
                      BadCase{test_domain::kBadUnknownModel, "bad_unknown_model.pbtxt", "bad_unknown_model.pbtxt:13:",
                              "vehicle_type[0].driver.car_following"}),
    [](const ::testing::TestParamInfo<BadCase>& param) {
      std::string n = param.param.file;
      return n.substr(4, n.find('.') - 4);
    });

TEST(BadCommandLine, UnknownOptionsAndValuesAreRefused) {
  EXPECT_EQ(run_command(bin("entourage") + " run " + source("scenarios/freeway.pbtxt") + " --speed 3").exit_code, 2);
  EXPECT_EQ(run_command(bin("entourage") + " run " + source("scenarios/freeway.pbtxt") + " --seed x").exit_code, 2);
  EXPECT_EQ(run_command(bin("entourage") + " run " + source("scenarios/freeway.pbtxt") + " --lockstep --realtime").exit_code, 2);
  EXPECT_EQ(run_command(bin("entourage") + " frobnicate").exit_code, 2);
  EXPECT_EQ(run_command(bin("entourage-meso") + " --scenario " + source("scenarios/freeway.pbtxt") + " --regions middle").exit_code, 2);
  EXPECT_EQ(run_command(bin("entourage-recorder") + " --scenario " + source("scenarios/freeway.pbtxt")).exit_code, 2);
}

TEST(Executables, EveryServiceHasHelp) {
  for (const char* name : {"entourage", "entourage-ego", "entourage-generator", "entourage-micro", "entourage-meso",
                           "entourage-director", "entourage-recorder"}) {
    const CommandResult r = run_command(bin(name) + " --help");
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("usage:"), std::string::npos) << name << "\n" << r.output;
  }
}

TEST(Executables, ExportRefusesWhatIsNotARecording) {
  const CommandResult r = run_command(bin("entourage") + " export " + source("scenarios/freeway.pbtxt") + " --csv /tmp/x");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("freeway.pbtxt"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace entourage::testing
