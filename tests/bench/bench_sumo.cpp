// entourage-bench-sumo: the SUMO peer case (tests/bench/sumo/, tests/bench/sumo_freeway.pbtxt) run
// through Entourage's micro core (the road simulation, traffic/road_sim.hpp) and through SUMO, one
// after the other on the same machine in one run. Prints vehicle updates per second (SUMO's `UPS`)
// and the mean trip speed of both, and the ratio. A measurement, not a test: nothing is asserted.
//
// SUMO is Debian's `sumo` package (`deploy/setup.sh --bench` installs it); without it only
// Entourage's figures are printed.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include "bench_util.hpp"
#include "cli/args.hpp"
#include "core/units.hpp"
#include "roadsim/core/road_experiment.hpp"
#include "scenario/loader.hpp"

namespace entourage {
namespace {

namespace fs = std::filesystem;

struct Figures {
  std::string who;
  double vehicle_updates = 0.0;
  double wall_s = 0.0;
  double cpu_s = -1.0;  // < 0: not measured
  double ups = 0.0;
  double mean_trip_speed_mps = 0.0;
  double trips = 0.0;
};

Figures run_entourage(const roadsim::Prepared& prepared, const roadsim::ExperimentConfig& c, const std::string& who) {
  const std::clock_t cpu0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  const roadsim::ExperimentResult r = roadsim::run_experiment(prepared, c);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  Figures f;
  f.who = who;
  f.vehicle_updates = static_cast<double>(r.vehicle_updates);
  f.wall_s = wall;
  f.cpu_s = cpu;
  f.ups = wall > 0.0 ? f.vehicle_updates / wall : 0.0;
  f.mean_trip_speed_mps = r.mean_trip_speed_mps;
  f.trips = static_cast<double>(r.counters.trips);
  return f;
}

// Runs a shell command, returns its exit status and everything it printed.
int capture(const std::string& command, std::string* output) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return -1;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) *output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The number after `key` on the first line (after `after`, if given) that contains it.
std::optional<double> number_after(const std::string& text, const std::string& key, const std::string& after = "") {
  std::size_t from = 0;
  if (!after.empty()) {
    from = text.find(after);
    if (from == std::string::npos) return std::nullopt;
  }
  const std::size_t at = text.find(key, from);
  if (at == std::string::npos) return std::nullopt;
  try {
    return std::stod(text.substr(at + key.size()));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string quote(const fs::path& p) { return "'" + p.string() + "'"; }

std::optional<Figures> run_sumo(const fs::path& case_dir, const fs::path& work_dir, double duration_s,
                                std::string* problem) {
  std::error_code ec;
  fs::create_directories(work_dir, ec);
  for (const char* f : {"nodes.nod.xml", "edges.edg.xml", "freeway.rou.xml", "freeway.sumocfg"}) {
    fs::copy_file(case_dir / f, work_dir / f, fs::copy_options::overwrite_existing, ec);
    if (ec) {
      *problem = "cannot copy " + (case_dir / f).string() + " to " + work_dir.string() + ": " + ec.message();
      return std::nullopt;
    }
  }
  std::string out;
  const std::string cd = "cd " + quote(work_dir) + " && ";
  if (capture(cd + "netconvert --node-files nodes.nod.xml --edge-files edges.edg.xml -o freeway.net.xml", &out) != 0) {
    *problem = "netconvert failed:\n" + out;
    return std::nullopt;
  }
  out.clear();
  char end[64];
  std::snprintf(end, sizeof end, "%.1f", duration_s);
  if (capture(cd + "sumo -c freeway.sumocfg --end " + end, &out) != 0) {
    *problem = "sumo failed:\n" + out;
    return std::nullopt;
  }
  const auto ups = number_after(out, "UPS:");
  const auto wall = number_after(out, "Duration:", "Performance");
  const auto speed = number_after(out, "Speed:", "Statistics");
  const auto trips = number_after(out, "Statistics (avg of ");
  if (!ups || !wall) {
    *problem = "no UPS or Duration in SUMO's output:\n" + out;
    return std::nullopt;
  }
  Figures f;
  f.who = "SUMO (IDM, LC2013)";
  f.ups = *ups;
  f.wall_s = *wall;
  f.vehicle_updates = *ups * *wall;
  f.mean_trip_speed_mps = speed.value_or(0.0);
  f.trips = trips.value_or(0.0);
  return f;
}

void print_row(const Figures& f) {
  char cpu[32] = "     -";
  if (f.cpu_s >= 0.0) std::snprintf(cpu, sizeof cpu, "%6.2f", f.cpu_s);
  std::printf("  %-40s %14.0f %8.2f %s %12.0f %9.2f m/s (%5.1f km/h) over %.0f trips\n", f.who.c_str(),
              f.vehicle_updates, f.wall_s, cpu, f.ups, f.mean_trip_speed_mps, mps_to_kph(f.mean_trip_speed_mps),
              f.trips);
}

int run(int argc, char** argv) {
  std::string scenario_path = std::string(ENTOURAGE_SOURCE_DIR) + "/tests/bench/sumo_freeway.pbtxt";
  std::string case_dir = std::string(ENTOURAGE_SOURCE_DIR) + "/tests/bench/sumo";
  std::string work_dir = (fs::temp_directory_path() / "entourage-bench-sumo").string();
  double duration_s = 3600.0;
  bool no_sumo = false;
  roadsim::ExperimentConfig c;
  c.seed = 42;
  cli::Args args("entourage-bench-sumo",
                 "Runs the SUMO peer case (a 20 km two-lane freeway, 3000 veh/h of IDM cars for an hour) through "
                 "Entourage's micro core and through SUMO, and prints vehicle updates per second and mean trip "
                 "speed of both and their ratio.");
  args.option("scenario", "FILE", "the case as an Entourage scenario (default tests/bench/sumo_freeway.pbtxt)",
              &scenario_path);
  args.option("sumo-case", "DIR", "the case's SUMO files (default tests/bench/sumo)", &case_dir);
  args.option("work-dir", "DIR", "where SUMO's network is built and SUMO runs (default a temporary directory)",
              &work_dir);
  args.option("duration", "S", "simulated time (default 3600)", &duration_s);
  args.option("seed", "N", "seed of Entourage's random stream (default 42, as SUMO's)", &c.seed);
  args.flag("no-sumo", "do not run SUMO", &no_sumo);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  const auto loaded = scenario::load_file(scenario_path);
  if (!loaded.ok()) {
    for (const auto& p : loaded.problems) std::cerr << p.to_string() << "\n";
    return 2;
  }
  c.scenario_road = true;
  c.duration_s = duration_s;
  c.warmup_s = std::min(300.0, 0.5 * duration_s);
  const roadsim::Prepared prepared = roadsim::prepare(loaded.config, c);
  if (!prepared.ok()) {
    std::cerr << "entourage-bench-sumo: " << prepared.error << "\n";
    return 2;
  }
  const ScenarioConfig& sc = prepared.scenario;
  std::printf("SUMO peer case: %.0f km, %d lanes, %.0f km/h, %.0f veh/h, %.0f s at %.2f s steps, one core\n",
              sc.road.length_m / 1000.0, sc.road.lanes_forward, mps_to_kph(sc.road.speed_limit_mps),
              per_second_to_per_hour(sc.forward.flow_veh_per_s), duration_s, sc.step_s);
  std::printf("  %-40s %14s %8s %6s %12s %s\n", "", "vehicle updates", "wall s", "CPU s", "updates/s",
              "mean trip speed");
  const Figures ours = run_entourage(prepared, c, "Entourage (IDM, MOBIL every 0.5 s)");
  print_row(ours);
  std::fflush(stdout);
  roadsim::ExperimentConfig every_step = c;
  every_step.decision_interval_s = 0.0;
  const roadsim::Prepared prepared_every_step = roadsim::prepare(loaded.config, every_step);
  const Figures ours_every_step = run_entourage(prepared_every_step, every_step, "Entourage (IDM, MOBIL every step)");
  print_row(ours_every_step);
  std::fflush(stdout);
  if (no_sumo) return 0;
  if (!bench::on_path("sumo") || !bench::on_path("netconvert")) {
    std::printf("  SUMO is not installed (deploy/setup.sh --bench installs Debian's sumo): no comparison\n");
    return 0;
  }
  std::string problem;
  const auto sumo = run_sumo(case_dir, work_dir, duration_s, &problem);
  if (!sumo) {
    std::cerr << "entourage-bench-sumo: " << problem << "\n";
    return 1;
  }
  print_row(*sumo);
  if (sumo->ups > 0.0) {
    std::printf("ratio of vehicle updates per second, Entourage / SUMO: %.1f (MOBIL every 0.5 s), %.1f (every step); "
                "goal >= 10\n",
                ours.ups / sumo->ups, ours_every_step.ups / sumo->ups);
  }
  if (sumo->mean_trip_speed_mps > 0.0) {
    std::printf("mean trip speed, Entourage / SUMO: %.3f\n", ours.mean_trip_speed_mps / sumo->mean_trip_speed_mps);
  }
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) { return entourage::run(argc, argv); }
