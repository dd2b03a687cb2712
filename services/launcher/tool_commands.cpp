// entourage check / export / verify / models: the commands that work on files, without DDS.
#include <filesystem>
#include <iostream>

#include "behaviour/model_registry.hpp"
#include "cli/args.hpp"
#include "core/units.hpp"
#include "launcher/commands.hpp"
#include "launcher/report.hpp"
#include "recording/csv_tables.hpp"
#include "recording/recording.hpp"
#include "recording/tables.hpp"
#include "scenario/loader.hpp"

namespace entourage::launcher {

namespace {

// The scenario a recording was made with (its attached text), for type names and the window;
// `source` names the text in problems.
std::optional<ScenarioConfig> recorded_scenario(const std::string& text, const std::string& source) {
  auto sc = scenario::load_text(text, source);
  if (!sc.ok()) {
    for (const auto& p : sc.problems) std::cerr << p.to_string() << "\n";
    return std::nullopt;
  }
  return sc.config;
}

std::vector<std::string> type_names(const ScenarioConfig& sc) {
  std::vector<std::string> names;
  for (const auto& t : sc.vehicle_types) names.push_back(t.name);
  return names;
}

struct Opened {
  recording::Tables tables;
  ScenarioConfig scenario;
};

// Reads an MCAP recording as rows, with the scenario attached to it; prints what is wrong and
// returns nullopt.
std::optional<Opened> open_recording(const std::string& path, const char* command) {
  std::string error;
  const auto rec = recording::read_recording(path, &error);
  if (!rec) {
    std::cerr << "entourage " << command << ": " << error << "\n";
    return std::nullopt;
  }
  auto sc = recorded_scenario(rec->info.scenario_text, path + " (attached " + rec->info.scenario_file + ")");
  if (!sc) return std::nullopt;
  return Opened{recording::tables_from(*rec, type_names(*sc)), std::move(*sc)};
}

// Reads a directory written by `entourage export`, with the scenario.pbtxt in it; prints what is
// wrong and returns nullopt.
std::optional<Opened> open_export(const std::string& dir, const char* command) {
  std::string error;
  auto tables = recording::read_csv(dir, &error);
  if (!tables) {
    std::cerr << "entourage " << command << ": " << error << "\n";
    return std::nullopt;
  }
  auto sc = recorded_scenario(tables->info.scenario_text, dir + "/" + recording::kScenarioFile);
  if (!sc) return std::nullopt;
  return Opened{std::move(*tables), std::move(*sc)};
}

}  // namespace

int check_command(int argc, char** argv) {
  std::string path;
  cli::Args args("entourage check", "Validates a scenario: exits 0, or prints every problem and exits 2.");
  args.positional("SCENARIO", "scenario file", &path);
  if (const auto rc = args.parse_or_exit(argc, argv, 2)) return *rc;
  const auto sc = scenario::load_file(path);
  if (!sc.ok()) {
    for (const auto& p : sc.problems) std::cerr << p.to_string() << "\n";
    std::cerr << path << ": " << sc.problems.size() << " problem(s)\n";
    return 2;
  }
  const ScenarioConfig& c = sc.config;
  std::cout << path << ": ok: \"" << c.name << "\", " << c.road.length_m / 1000.0 << " km of "
            << (c.road.kind == RoadKind::kRural ? "rural road" : "freeway") << " with " << c.road.lanes_forward << "+"
            << c.road.lanes_backward << " lanes, " << per_second_to_per_hour(c.forward.flow_veh_per_s) << "+"
            << per_second_to_per_hour(c.backward.flow_veh_per_s) << " veh/h, " << c.vehicle_types.size()
            << " vehicle types, " << c.plays.size() << " plays, " << c.duration_s << " s\n";
  return 0;
}

int export_command(int argc, char** argv) {
  std::string path;
  std::string dir;
  cli::Args args("entourage export",
                 "Writes a recording as CSV: vehicles.csv, ego.csv, handoffs.csv, plays.csv, commands.csv, with "
                 "run.csv and scenario.pbtxt, which entourage verify DIR reads back.");
  args.positional("RECORDING", "an MCAP recording made by entourage run", &path);
  args.option("csv", "DIR", "directory to write the CSV files to; required", &dir);
  if (const auto rc = args.parse_or_exit(argc, argv, 2)) return *rc;
  if (dir.empty()) {
    std::cerr << "entourage export: --csv DIR is required\n";
    return 2;
  }
  const auto opened = open_recording(path, "export");
  if (!opened) return 1;
  const recording::Tables& tables = opened->tables;
  std::string error;
  if (!recording::write_csv(tables, dir, &error)) {
    std::cerr << "entourage export: " << error << "\n";
    return 1;
  }
  std::cout << "wrote " << tables.vehicles.size() << " vehicle rows, " << tables.ego.size() << " ego rows, "
            << tables.handoffs.size() << " handoffs, " << tables.plays.size() << " play reports and "
            << tables.commands.size() << " director commands to " << dir << "/\n";
  return 0;
}

int verify_command(int argc, char** argv) {
  std::string path;
  cli::Args args("entourage verify",
                 "Checks a recording against the design's invariants and prints its figures; exits 1 if an "
                 "invariant is violated, 2 if the input cannot be read.");
  args.positional("RECORDING", "an MCAP recording made by entourage run, or a directory written by entourage export",
                  &path);
  if (const auto rc = args.parse_or_exit(argc, argv, 2)) return *rc;
  const auto opened =
      std::filesystem::is_directory(path) ? open_export(path, "verify") : open_recording(path, "verify");
  if (!opened) return 2;
  return print_report({path, "", opened->scenario, 0.0, false, {}, {}, {}}, opened->tables, std::cout) ? 0 : 1;
}

int models_command(int argc, char** argv) {
  cli::Args args("entourage models", "Lists the behavioural models a scenario can name.");
  if (const auto rc = args.parse_or_exit(argc, argv, 2)) return *rc;
  for (const auto& m : all_models()) std::cout << m.kind << "  " << m.name << "  " << m.description << "\n";
  return 0;
}

}  // namespace entourage::launcher
