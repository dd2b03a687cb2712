// The CSV export read back (csv_tables, csv_file): rows come back as the very same values, so
// verify prints the same figures from a directory as from its recording; every kind of bad input
// is refused with file, line, column and the column's name, never a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "recording/csv_file.hpp"
#include "recording/csv_tables.hpp"

namespace entourage::recording {
namespace {

namespace fs = std::filesystem;

std::string fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("entourage_csv_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void put(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Replaces the 1-based line `n` of a file.
void replace_line(const std::string& path, std::size_t n, const std::string& text) {
  std::istringstream in(bytes(path));
  std::string out;
  std::string line;
  for (std::size_t i = 1; std::getline(in, line); ++i) out += (i == n ? text : line) + "\n";
  put(path, out);
}

std::string line_of(const std::string& path, std::size_t n) {
  std::istringstream in(bytes(path));
  std::string line;
  for (std::size_t i = 1; i <= n; ++i) std::getline(in, line);
  return line;
}

// Values whose shortest decimal form is long, tiny, huge or negative, names with commas and quotes.
Tables sample() {
  Tables t;
  t.info.scenario_name = "freeway, short";
  t.info.scenario_file = "scenarios/freeway.pbtxt";
  t.info.scenario_text = "name: \"freeway\"\n# a comment, with \"quotes\"\n";
  t.info.seed = 18446744073709551615ULL;
  t.info.mode = "lockstep";
  t.info.step_s = 0.1;
  t.info.peers = "ego,generator,micro,meso,director,recorder";
  t.undecodable = 3;
  for (std::uint64_t k = 1; k <= 3; ++k) {
    const double time_s = 0.1 * static_cast<double>(k);  // 0.30000000000000004 at k = 3
    t.ego.push_back({k, time_s, 1000.0 + 0.1 + 0.2, -5.25, 1e-300, -1e300, 3.141592653589793, 30.000000000000004, -0.0,
                     0, 4.6, 1.8});
    t.vehicles.push_back({k, time_s, 7, "micro", "inner", 1, 0, 1, 1100.0 / 3.0, -5.25, 2.5e-7, 1e22, -1.0 / 3.0,
                          29.999999999999996, -2.5, 4.5, 1.8, "car, \"small\""});
    t.vehicles.push_back({k, time_s, 4000000000U, "service-771", "outer_rear", -1, 1, 1, 900.0, 1.75, 0, 0, 0, 25.0,
                          0, 12.0, 2.5, "truck", k == 2 ? "transported" : "autonomous"});
  }
  t.handoffs.push_back({1, 0.1, 7, 1, "generator", "micro", "inner", "initial_fill", 0, 1100.0 / 3.0, 30.0});
  t.handoffs.push_back({3, 0.30000000000000004, 7, 2, "micro", "none", "outside", "left_window", 0, 2e5, 0.0});
  t.plays.push_back({2, 0.2, 1, "lead vehicle brakes", 7, 1300.5, -1.0, 2, 1, 3, -7.25, 1.0 / 3.0, "outcome: braked, \"hard\""});
  t.commands.push_back({2, 0.2, 4000000000U, 1, "controlled", 1.0 / 3.0, 2.5, 7.25, 1e-3, -1, true, 0.0, 2});
  t.commands.push_back({3, 0.30000000000000004, 7, 1, "releasing", 0.0, 1.0, 1.0, 2.0, 15, false, 3.5, 0});
  t.commands.push_back({3, 0.30000000000000004, 8, 1, "withdrawn", 0.0, 1.0, 1.0, 2.0, -1, false, 0.0, 0});
  return t;
}

std::string exported(const std::string& name) {
  const std::string dir = fresh_dir(name);
  std::string error;
  EXPECT_TRUE(write_csv(sample(), dir, &error)) << error;
  return dir;
}

// The error of reading `dir` back; fails the test if it reads.
std::string refusal(const std::string& dir) {
  std::string error;
  const auto t = read_csv(dir, &error);
  EXPECT_FALSE(t) << "read without complaint";
  return error;
}

TEST(CsvTables, RoundTripGivesTheSameValues) {
  const Tables t = sample();
  const std::string dir = exported("round_trip");
  std::string error;
  const auto back = read_csv(dir, &error);
  ASSERT_TRUE(back) << error;
  ASSERT_EQ(back->vehicles.size(), t.vehicles.size());
  ASSERT_EQ(back->ego.size(), t.ego.size());
  ASSERT_EQ(back->handoffs.size(), t.handoffs.size());
  ASSERT_EQ(back->plays.size(), t.plays.size());
  EXPECT_EQ(back->vehicles[4].time_s, 0.1 * 3.0);  // exactly: no digits lost
  EXPECT_EQ(back->vehicles[4].s_m, 1100.0 / 3.0);
  EXPECT_EQ(back->vehicles[4].target_lane, 1);
  EXPECT_EQ(back->vehicles[4].type, "car, \"small\"");
  EXPECT_EQ(back->vehicles[5].id, 4000000000U);
  EXPECT_EQ(back->vehicles[5].owner, "service-771");
  EXPECT_EQ(back->ego[0].s_m, 1000.0 + 0.1 + 0.2);
  EXPECT_EQ(back->ego[0].x_m, 1e-300);
  EXPECT_EQ(back->ego[0].length_m, 4.6);
  EXPECT_EQ(back->handoffs[0].reason, "initial_fill");
  EXPECT_EQ(back->plays[0].detail, "outcome: braked, \"hard\"");
  EXPECT_EQ(back->vehicles[3].control, "transported");  // step 2, vehicle 4000000000
  EXPECT_EQ(back->vehicles[2].control, "autonomous");
  ASSERT_EQ(back->commands.size(), 3U);
  EXPECT_EQ(back->commands[0].vehicle_id, 4000000000U);
  EXPECT_EQ(back->commands[0].mode, "controlled");
  EXPECT_EQ(back->commands[0].speed_mps, 1.0 / 3.0);
  EXPECT_EQ(back->commands[0].max_jerk_mps3, 1e-3);
  EXPECT_EQ(back->commands[0].lane, -1);
  EXPECT_TRUE(back->commands[0].force_lane);
  EXPECT_EQ(back->commands[0].indicator, 2U);
  EXPECT_EQ(back->commands[1].time_s, 0.30000000000000004);
  EXPECT_EQ(back->commands[1].mode, "releasing");
  EXPECT_FALSE(back->commands[1].force_lane);
  EXPECT_EQ(back->commands[1].lane, 15);
  EXPECT_EQ(back->commands[2].mode, "withdrawn");  // an oncoming vehicle taken off for a gap
  EXPECT_EQ(back->info.scenario_text, t.info.scenario_text);
  EXPECT_EQ(back->info.scenario_name, t.info.scenario_name);
  EXPECT_EQ(back->info.peers, t.info.peers);
  EXPECT_EQ(back->info.seed, t.info.seed);
  EXPECT_EQ(back->info.step_s, 0.1);
  EXPECT_EQ(back->undecodable, 3U);
  // Every other field: writing what was read gives the same bytes (distinct doubles are written
  // differently, so equal files mean equal values).
  const std::string again = fresh_dir("round_trip_again");
  ASSERT_TRUE(write_csv(*back, again, &error)) << error;
  for (const char* f : {kVehiclesFile, kEgoFile, kHandoffsFile, kPlaysFile, kCommandsFile, kRunFile, kScenarioFile}) {
    EXPECT_EQ(bytes(dir + "/" + f), bytes(again + "/" + f)) << f;
  }
}

TEST(CsvTables, RowsComeBackSortedByStepThenId) {
  const std::string dir = exported("sorted");
  const std::string path = dir + "/vehicles.csv";
  const std::string first = line_of(path, 2);
  replace_line(path, 2, line_of(path, 7));  // the last row first
  replace_line(path, 7, first);
  std::string error;
  const auto back = read_csv(dir, &error);
  ASSERT_TRUE(back) << error;
  for (std::size_t i = 1; i < back->vehicles.size(); ++i) {
    const auto& a = back->vehicles[i - 1];
    const auto& b = back->vehicles[i];
    EXPECT_TRUE(a.step < b.step || (a.step == b.step && a.id < b.id)) << i;
  }
}

TEST(CsvTables, AMissingFileIsNamed) {
  for (const char* f : {kVehiclesFile, kEgoFile, kHandoffsFile, kPlaysFile, kCommandsFile, kRunFile, kScenarioFile}) {
    const std::string dir = exported("missing");
    fs::remove(dir + "/" + f);
    EXPECT_EQ(refusal(dir), dir + "/" + f + ": cannot open: No such file or directory");
  }
}

TEST(CsvTables, AnEmptyFileIsRefused) {
  const std::string dir = exported("empty");
  put(dir + "/ego.csv", "");
  EXPECT_EQ(refusal(dir).rfind(dir + "/ego.csv:1: the file is empty; expected the header step,time_s,", 0), 0U);
}

TEST(CsvTables, AMissingColumnIsNamed) {
  const std::string dir = exported("missing_column");
  replace_line(dir + "/vehicles.csv", 1,
               "step,time_s,id,owner,region,direction,lane,s_m,d_m,x_m,y_m,heading_rad,speed_mps,accel_mps2,length_m,"
               "width_m,type");
  EXPECT_EQ(refusal(dir), dir + "/vehicles.csv:1:18: target_lane: missing (the header ends after column 17)");
}

TEST(CsvTables, AColumnOutOfPlaceIsNamed) {
  const std::string dir = exported("renamed_column");
  replace_line(dir + "/ego.csv", 1, "step,time_s,s_m,d_m,x_m,y_m,heading_rad,speed,accel_mps2,lane,length_m,width_m");
  EXPECT_EQ(refusal(dir).rfind(dir + "/ego.csv:1:8: speed_mps: expected here, found \"speed\"", 0), 0U);
}

TEST(CsvTables, AnExtraColumnIsRefused) {
  const std::string dir = exported("extra_column");
  replace_line(dir + "/handoffs.csv", 1,
               "step,time_s,vehicle_id,sequence,from,to_role,to_region,reason,lane,s_m,speed_mps,note");
  EXPECT_EQ(refusal(dir).rfind(dir + "/handoffs.csv:1:12: unexpected column \"note\"", 0), 0U);
}

TEST(CsvTables, ANonNumberIsNamedWithLineAndColumn) {
  const std::string dir = exported("non_number");
  std::string row = line_of(dir + "/ego.csv", 3);
  row.replace(row.find(",30.000000000000004,"), 20, ",fast,");
  replace_line(dir + "/ego.csv", 3, row);
  EXPECT_EQ(refusal(dir), dir + "/ego.csv:3:8: speed_mps: \"fast\" is not a number");
}

TEST(CsvTables, AnEmptyNumberIsRefused) {
  const std::string dir = exported("empty_number");
  replace_line(dir + "/handoffs.csv", 2, "1,0.1,7,1,generator,micro,inner,initial_fill,0,,30");
  EXPECT_EQ(refusal(dir), dir + "/handoffs.csv:2:10: s_m: \"\" is not a number");
}

TEST(CsvTables, AFractionWhereAWholeNumberBelongsIsRefused) {
  const std::string dir = exported("fraction");
  std::string row = line_of(dir + "/ego.csv", 2);
  replace_line(dir + "/ego.csv", 2, "1.5" + row.substr(1));
  EXPECT_EQ(refusal(dir), dir + "/ego.csv:2:1: step: \"1.5\" is not a whole number of 0 or more");
}

TEST(CsvTables, ANumberOutOfItsRangeIsRefused) {
  const std::string dir = exported("range");
  std::string row = line_of(dir + "/vehicles.csv", 3);  // step 1, vehicle 4000000000
  row.replace(row.find("4000000000"), 10, "5000000000");
  replace_line(dir + "/vehicles.csv", 3, row);
  EXPECT_EQ(refusal(dir), dir + "/vehicles.csv:3:3: id: \"5000000000\" is out of range");
}

TEST(CsvTables, AWrongNumberOfFieldsIsRefused) {
  const std::string dir = exported("field_count");
  const std::string row = line_of(dir + "/ego.csv", 4);
  replace_line(dir + "/ego.csv", 4, row.substr(0, row.rfind(',')));
  EXPECT_EQ(refusal(dir), dir + "/ego.csv:4:12: width_m: missing: the row has 11 fields, the header 12");
  replace_line(dir + "/ego.csv", 4, row + ",1");
  EXPECT_EQ(refusal(dir), dir + "/ego.csv:4:13: the row has 13 fields, the header 12");
  replace_line(dir + "/ego.csv", 4, "");
  EXPECT_EQ(refusal(dir), dir + "/ego.csv:4:2: time_s: missing: the row has 1 field, the header 12");
}

TEST(CsvTables, AnUnknownNameIsRefused) {
  const std::string dir = exported("unknown_name");
  std::string row = line_of(dir + "/vehicles.csv", 2);
  row.replace(row.find(",inner,"), 7, ",middle,");
  replace_line(dir + "/vehicles.csv", 2, row);
  EXPECT_EQ(refusal(dir),
            dir + "/vehicles.csv:2:5: region: \"middle\" is not one of outside,outer_rear,inner,outer_front");
  row.replace(row.find(",micro,"), 7, ",driver,");
  replace_line(dir + "/vehicles.csv", 2, row);
  EXPECT_EQ(refusal(dir).rfind(dir + "/vehicles.csv:2:4: owner: \"driver\" is not a service name", 0), 0U);
}

TEST(CsvTables, ABadCommandFieldIsNamed) {
  const std::string dir = exported("bad_command");
  std::string row = line_of(dir + "/commands.csv", 2);
  EXPECT_EQ(row, "2,0.2,4000000000,1,controlled,0.3333333333333333,2.5,7.25,0.001,-1,1,0,2");
  replace_line(dir + "/commands.csv", 2, "2,0.2,4000000000,1,steered,0.3333333333333333,2.5,7.25,0.001,-1,1,0,2");
  EXPECT_EQ(refusal(dir), dir + "/commands.csv:2:5: mode: \"steered\" is not one of "
                              "autonomous,transported,controlled,releasing,withdrawn,unknown");
  replace_line(dir + "/commands.csv", 2, "2,0.2,4000000000,1,controlled,0.3333333333333333,2.5,7.25,0.001,-1,yes,0,2");
  EXPECT_EQ(refusal(dir), dir + "/commands.csv:2:11: force_lane: \"yes\" is not one of 0,1");
  std::string vehicles = line_of(dir + "/vehicles.csv", 2);
  replace_line(dir + "/vehicles.csv", 2, vehicles.substr(0, vehicles.rfind(',')) + ",driven");
  EXPECT_EQ(refusal(dir).rfind(dir + "/vehicles.csv:2:19: control: \"driven\" is not one of", 0), 0U);
}

TEST(CsvTables, BrokenQuotingIsRefused) {
  const std::string dir = exported("quoting");
  const std::string row = line_of(dir + "/plays.csv", 2);
  replace_line(dir + "/plays.csv", 2, row.substr(0, row.size() - 1));  // the closing quote of detail
  EXPECT_EQ(refusal(dir), dir + "/plays.csv:2:13: detail: a quoted field is not closed on its line");
  replace_line(dir + "/plays.csv", 2, "2,0.2,1,\"lead\" vehicle,7,1300.5,-1,x");
  EXPECT_EQ(refusal(dir), dir + "/plays.csv:2:4: name: a quoted field goes on after its closing quote");
  replace_line(dir + "/plays.csv", 2, "2,0.2,1,lead \"vehicle\",7,1300.5,-1,x");
  EXPECT_EQ(refusal(dir), dir + "/plays.csv:2:4: name: a quote inside a field that does not start with one");
}

TEST(CsvTables, TheRunFileHoldsExactlyOneRow) {
  const std::string dir = exported("run_rows");
  const std::string run = bytes(dir + "/run.csv");
  put(dir + "/run.csv", run.substr(0, run.find('\n') + 1));
  EXPECT_EQ(refusal(dir), dir + "/run.csv:2: the run's row is missing");
  put(dir + "/run.csv", run + run.substr(run.find('\n') + 1));
  EXPECT_EQ(refusal(dir), dir + "/run.csv:3: a second row; run.csv has one");
}

TEST(CsvFile, SplitsQuotedFieldsAndEmptyOnes) {
  std::vector<std::string> f;
  std::size_t bad = 0;
  std::string what;
  ASSERT_TRUE(csv::split_fields("a,\"b,\"\"c\"\"\",,\"\"", &f, &bad, &what)) << what;
  EXPECT_EQ(f, (std::vector<std::string>{"a", "b,\"c\"", "", ""}));
  ASSERT_TRUE(csv::split_fields("", &f, &bad, &what));
  EXPECT_EQ(f, std::vector<std::string>{""});
}

TEST(CsvFile, AnEmptyFirstFieldKeepsItsPlace) {
  csv::LineWriter l;
  EXPECT_EQ(l.add("").add("").add(1).finish(), ",,1\n");
}

TEST(CsvFile, WritesTheShortestNumberThatReadsBack) {
  csv::LineWriter l;
  EXPECT_EQ(l.add(0.1).add(0.1 + 0.2).add(1e22).add(-0.5).add(std::uint64_t{7}).add(-3).finish(),
            "0.1,0.30000000000000004,1e+22,-0.5,7,-3\n");
  EXPECT_EQ(l.add("plain").add("with, comma").add("with \"quote\"").finish(),
            "plain,\"with, comma\",\"with \"\"quote\"\"\"\n");
}

}  // namespace
}  // namespace entourage::recording
