// `entourage verify` on an exported CSV directory: a short run over DDS, exported, gives the same
// checks and figures from the directory as from the recording, so anyone can repeat them from the
// CSV files alone; a directory that cannot be read is refused with exit code 2 and a message that
// names file, line and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "process_util.hpp"
#include "../test_domains.hpp"
#include "recording/csv_tables.hpp"

namespace entourage::testing {
namespace {

constexpr int kDomainVerifyCsv = test_domain::kVerifyCsv;

// The report without its last line but one, "recording: PATH (N samples)", which names the input;
// that line's sample count is returned in *samples.
std::string figures(const std::string& report, std::string* samples) {
  std::istringstream in(report);
  std::string out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("  recording: ", 0) == 0) {
      *samples = line.substr(line.rfind('('));
      continue;
    }
    out += line + "\n";
  }
  return out;
}

TEST(VerifyCsv, TheExportGivesTheSameChecksAndFiguresAsTheRecording) {
  const std::string dir = fresh_dir("verify_csv");
  const CommandResult run = run_command(bin("entourage") + " run " + source("scenarios/freeway.pbtxt") +
                                        " --duration 30 --quiet --domain " + std::to_string(kDomainVerifyCsv) +
                                        " --record " + dir + "/r.mcap");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(no_process_uses_domain(kDomainVerifyCsv));
  const CommandResult exported = run_command(bin("entourage") + " export " + dir + "/r.mcap --csv " + dir + "/csv");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;

  const CommandResult from_mcap = run_command(bin("entourage") + " verify " + dir + "/r.mcap");
  const CommandResult from_csv = run_command(bin("entourage") + " verify " + dir + "/csv");
  ASSERT_EQ(from_mcap.exit_code, 0) << from_mcap.output;
  ASSERT_EQ(from_csv.exit_code, 0) << from_csv.output;
  std::string samples_mcap;
  std::string samples_csv;
  const std::string mcap_figures = figures(from_mcap.output, &samples_mcap);
  EXPECT_EQ(mcap_figures, figures(from_csv.output, &samples_csv));
  EXPECT_EQ(samples_mcap, samples_csv);
  EXPECT_NE(from_csv.output.find("  recording: " + dir + "/csv ("), std::string::npos) << from_csv.output;
  for (const char* part : {"simulated 30.0 s (300 steps)", "flow forward", "catch-ups against the moving-observer",
                           "ok     no_overlap", "ok     ego_interacts"}) {
    EXPECT_NE(mcap_figures.find(part), std::string::npos) << part << "\n" << mcap_figures;
  }
  std::filesystem::remove_all(dir);
}

// A directory written from a few rows with the default scenario, then broken in several ways.
std::string small_export(const std::string& name) {
  const std::string dir = fresh_dir(name);
  recording::Tables t;
  t.info.scenario_file = "scenarios/freeway.pbtxt";
  t.info.scenario_text = file_bytes(source("scenarios/freeway.pbtxt"));
  for (std::uint64_t k = 1; k <= 3; ++k) {
    t.ego.push_back({k, 0.1 * static_cast<double>(k), 1000.0, -5.25, 0, 0, 0, 30.0, 0, 0, 4.6, 1.8});
  }
  std::string error;
  EXPECT_TRUE(recording::write_csv(t, dir, &error)) << error;
  return dir;
}

TEST(VerifyCsv, AnUnreadableExportExitsTwoNamingFileLineAndColumn) {
  const std::string dir = small_export("verify_csv_bad");
  const std::string ego = file_bytes(dir + "/ego.csv");
  {
    std::ofstream out(dir + "/ego.csv", std::ios::binary);
    out << ego.substr(0, ego.find("\n3,")) << "\n3,0.3,1000,-5.25,0,0,0,fast,0,0,4.6,1.8\n";
  }
  CommandResult r = run_command(bin("entourage") + " verify " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/ego.csv:4:8: speed_mps: \"fast\" is not a number"), std::string::npos) << r.output;

  std::filesystem::remove(dir + "/ego.csv");
  r = run_command(bin("entourage") + " verify " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/ego.csv: cannot open"), std::string::npos) << r.output;

  const std::string good = small_export("verify_csv_bad_scenario");
  {
    std::ofstream out(good + "/scenario.pbtxt", std::ios::binary);
    out << "name: \"broken\"\nroad { lanes_forward: -1 }\n";
  }
  r = run_command(bin("entourage") + " verify " + good);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(good + "/scenario.pbtxt:"), std::string::npos) << r.output;

  r = run_command(bin("entourage") + " verify " + source("scenarios/freeway.pbtxt"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(good);
}

}  // namespace
}  // namespace entourage::testing
