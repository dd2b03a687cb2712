#include "recording/csv_tables.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace entourage::recording {

const char* const kVehiclesFile = "vehicles.csv";
const char* const kEgoFile = "ego.csv";
const char* const kHandoffsFile = "handoffs.csv";
const char* const kPlaysFile = "plays.csv";
const char* const kCommandsFile = "commands.csv";
const char* const kRunFile = "run.csv";
const char* const kScenarioFile = "scenario.pbtxt";

// New columns go at the end, so that readers of the earlier ones by position still work.
const csv::Columns kVehicleColumns{"step",  "time_s",      "id",        "owner",      "region",   "direction",
                                   "lane",  "s_m",         "d_m",       "x_m",        "y_m",      "heading_rad",
                                   "speed_mps", "accel_mps2", "length_m", "width_m",   "type",     "target_lane",
                                   "control"};
const csv::Columns kEgoColumns{"step",      "time_s",     "s_m",  "d_m",      "x_m",    "y_m",
                               "heading_rad", "speed_mps", "accel_mps2", "lane", "length_m", "width_m"};
const csv::Columns kHandoffColumns{"step",    "time_s",    "vehicle_id", "sequence", "from", "to_role",
                                   "to_region", "reason", "lane",       "s_m",      "speed_mps"};
const csv::Columns kPlayColumns{"step",    "time_s",  "play_id",          "name",           "phase",
                                "ego_s_m", "estimated_start_time_s", "actors", "created", "cleared",
                                "position_error_m", "speed_error_mps", "detail"};
const csv::Columns kCommandColumns{"step",       "time_s",     "vehicle_id",    "play_id", "mode",
                                   "speed_mps",  "accel_mps2", "decel_mps2",    "max_jerk_mps3", "lane",
                                   "force_lane", "lane_change_duration_s", "indicator"};
const csv::Columns kRunColumns{"scenario_name", "scenario_file", "seed",   "mode",
                               "step_s",        "peers",         "undecodable_messages"};

namespace {

// The words the export writes in its name columns (tables.cpp, core/ids.cpp, traffic/handoff.cpp).
const std::vector<std::string_view> kRegions{"outside", "outer_rear", "inner", "outer_front"};
const std::vector<std::string_view> kToRoles{"none", "micro", "meso", "director", "other"};
const std::vector<std::string_view> kReasons{"birth", "initial_fill", "border", "left_window", "director", "unknown"};
const std::vector<std::string_view> kControlModes{"autonomous", "transported", "controlled", "releasing", "withdrawn",
                                                  "unknown"};
const std::vector<std::string_view> kFlags{"0", "1"};

std::string in_dir(const std::string& dir, const char* file) { return dir + "/" + file; }

// ---- writing ----

// Writes the header and one line per row; false with *error if the file cannot be written.
template <typename Row, typename AddFields>
bool write_file(const std::string& path, const csv::Columns& columns, const std::vector<Row>& rows,
                AddFields add_fields, std::string* error) {
  std::ofstream out(path, std::ios::binary);
  out << csv::header_line(columns);
  csv::LineWriter line;
  for (const Row& row : rows) {
    add_fields(line, row);
    out << line.finish();
  }
  out.close();
  if (!out) *error = "cannot write " + path;
  return static_cast<bool>(out);
}

void add_vehicle(csv::LineWriter& l, const VehicleRow& x) {
  l.add(x.step).add(x.time_s).add(x.id).add(x.owner).add(x.region).add(x.direction).add(x.lane);
  l.add(x.s_m).add(x.d_m).add(x.x_m).add(x.y_m).add(x.heading_rad).add(x.speed_mps).add(x.accel_mps2);
  l.add(x.length_m).add(x.width_m).add(x.type).add(x.target_lane).add(x.control);
}

void add_ego(csv::LineWriter& l, const EgoRow& x) {
  l.add(x.step).add(x.time_s).add(x.s_m).add(x.d_m).add(x.x_m).add(x.y_m).add(x.heading_rad).add(x.speed_mps);
  l.add(x.accel_mps2).add(x.lane).add(x.length_m).add(x.width_m);
}

void add_handoff(csv::LineWriter& l, const HandoffRow& x) {
  l.add(x.step).add(x.time_s).add(x.vehicle_id).add(x.sequence).add(x.from).add(x.to_role).add(x.to_region);
  l.add(x.reason).add(x.lane).add(x.s_m).add(x.speed_mps);
}

void add_play(csv::LineWriter& l, const PlayRow& x) {
  l.add(x.step).add(x.time_s).add(x.play_id).add(x.name).add(x.phase).add(x.ego_s_m).add(x.estimated_start_time_s);
  l.add(x.actors).add(x.created).add(x.cleared).add(x.position_error_m).add(x.speed_error_mps).add(x.detail);
}

void add_command(csv::LineWriter& l, const CommandRow& x) {
  l.add(x.step).add(x.time_s).add(x.vehicle_id).add(x.play_id).add(x.mode).add(x.speed_mps).add(x.accel_mps2);
  l.add(x.decel_mps2).add(x.max_jerk_mps3).add(x.lane).add(x.force_lane ? "1" : "0").add(x.lane_change_duration_s);
  l.add(x.indicator);
}

struct RunRow {
  RecordingInfo info;
  std::uint64_t undecodable = 0;
};

void add_run(csv::LineWriter& l, const RunRow& x) {
  l.add(x.info.scenario_name).add(x.info.scenario_file).add(x.info.seed).add(x.info.mode).add(x.info.step_s);
  l.add(x.info.peers).add(x.undecodable);
}

bool write_text(const std::string& path, const std::string& text, std::string* error) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) *error = "cannot write " + path;
  return static_cast<bool>(out);
}

// ---- reading ----

std::string service(csv::Reader& in) {
  std::string name = in.text();
  if (!role_of_service(name)) in.fail("\"" + name + "\" is not a service name (ego, generator, micro, meso, ...)");
  return name;
}

VehicleRow read_vehicle(csv::Reader& in) {
  VehicleRow r;
  r.step = in.u64();
  r.time_s = in.number();
  r.id = in.u32();
  r.owner = service(in);
  r.region = in.word(kRegions);
  r.direction = in.integer();
  r.lane = in.integer();
  r.s_m = in.number();
  r.d_m = in.number();
  r.x_m = in.number();
  r.y_m = in.number();
  r.heading_rad = in.number();
  r.speed_mps = in.number();
  r.accel_mps2 = in.number();
  r.length_m = in.number();
  r.width_m = in.number();
  r.type = in.text();
  r.target_lane = in.integer();
  r.control = in.word(kControlModes);
  return r;
}

EgoRow read_ego(csv::Reader& in) {
  EgoRow r;
  r.step = in.u64();
  r.time_s = in.number();
  r.s_m = in.number();
  r.d_m = in.number();
  r.x_m = in.number();
  r.y_m = in.number();
  r.heading_rad = in.number();
  r.speed_mps = in.number();
  r.accel_mps2 = in.number();
  r.lane = in.integer();
  r.length_m = in.number();
  r.width_m = in.number();
  return r;
}

HandoffRow read_handoff(csv::Reader& in) {
  HandoffRow r;
  r.step = in.u64();
  r.time_s = in.number();
  r.vehicle_id = in.u32();
  r.sequence = in.u32();
  r.from = service(in);
  r.to_role = in.word(kToRoles);
  r.to_region = in.word(kRegions);
  r.reason = in.word(kReasons);
  r.lane = in.integer();
  r.s_m = in.number();
  r.speed_mps = in.number();
  return r;
}

PlayRow read_play(csv::Reader& in) {
  PlayRow r;
  r.step = in.u64();
  r.time_s = in.number();
  r.play_id = in.u32();
  r.name = in.text();
  r.phase = in.u32();
  r.ego_s_m = in.number();
  r.estimated_start_time_s = in.number();
  r.actors = in.u32();
  r.created = in.u32();
  r.cleared = in.u32();
  r.position_error_m = in.number();
  r.speed_error_mps = in.number();
  r.detail = in.text();
  return r;
}

CommandRow read_command(csv::Reader& in) {
  CommandRow r;
  r.step = in.u64();
  r.time_s = in.number();
  r.vehicle_id = in.u32();
  r.play_id = in.u32();
  r.mode = in.word(kControlModes);
  r.speed_mps = in.number();
  r.accel_mps2 = in.number();
  r.decel_mps2 = in.number();
  r.max_jerk_mps3 = in.number();
  r.lane = in.integer();
  r.force_lane = in.word(kFlags) == "1";
  r.lane_change_duration_s = in.number();
  r.indicator = in.u32();
  return r;
}

template <typename ReadRow>
auto read_rows(const std::string& path, const csv::Columns& columns, ReadRow read_row) {
  std::vector<decltype(read_row(std::declval<csv::Reader&>()))> rows;
  csv::Reader in(path, columns);
  while (in.next()) rows.push_back(read_row(in));
  return rows;
}

// run.csv: exactly one row.
void read_run(const std::string& path, Tables* t) {
  csv::Reader in(path, kRunColumns);
  if (!in.next()) throw csv::CsvError(path + ":2: the run's row is missing");
  t->info.scenario_name = in.text();
  t->info.scenario_file = in.text();
  t->info.seed = in.u64();
  t->info.mode = in.text();
  t->info.step_s = in.number();
  t->info.peers = in.text();
  t->undecodable = in.u64();
  if (in.next()) throw csv::CsvError(path + ":" + std::to_string(in.line()) + ": a second row; run.csv has one");
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw csv::CsvError(path + ": cannot open: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool write_csv(const Tables& t, const std::string& dir, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    *error = "cannot create " + dir + ": " + ec.message();
    return false;
  }
  const std::vector<RunRow> run{{t.info, t.undecodable}};
  return write_file(in_dir(dir, kVehiclesFile), kVehicleColumns, t.vehicles, add_vehicle, error) &&
         write_file(in_dir(dir, kEgoFile), kEgoColumns, t.ego, add_ego, error) &&
         write_file(in_dir(dir, kHandoffsFile), kHandoffColumns, t.handoffs, add_handoff, error) &&
         write_file(in_dir(dir, kPlaysFile), kPlayColumns, t.plays, add_play, error) &&
         write_file(in_dir(dir, kCommandsFile), kCommandColumns, t.commands, add_command, error) &&
         write_file(in_dir(dir, kRunFile), kRunColumns, run, add_run, error) &&
         write_text(in_dir(dir, kScenarioFile), t.info.scenario_text, error);
}

std::optional<Tables> read_csv(const std::string& dir, std::string* error) {
  try {
    Tables t;
    read_run(in_dir(dir, kRunFile), &t);
    t.info.scenario_text = read_text(in_dir(dir, kScenarioFile));
    t.vehicles = read_rows(in_dir(dir, kVehiclesFile), kVehicleColumns, read_vehicle);
    t.ego = read_rows(in_dir(dir, kEgoFile), kEgoColumns, read_ego);
    t.handoffs = read_rows(in_dir(dir, kHandoffsFile), kHandoffColumns, read_handoff);
    t.plays = read_rows(in_dir(dir, kPlaysFile), kPlayColumns, read_play);
    t.commands = read_rows(in_dir(dir, kCommandsFile), kCommandColumns, read_command);
    sort_rows(t);
    return t;
  } catch (const csv::CsvError& e) {
    *error = e.what();
    return std::nullopt;
  }
}

}  // namespace entourage::recording
