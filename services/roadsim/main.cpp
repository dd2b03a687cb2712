// entourage-roadsim: the micro region's driving on a whole road without a moving window, for
// calibration, fundamental diagrams and benchmarks (see README.md). An offline tool: no DDS.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/args.hpp"
#include "core/units.hpp"
#include "roadsim/core/road_experiment.hpp"
#include "scenario/loader.hpp"

namespace entourage {

namespace {

std::vector<double> parse_list(const std::string& text, bool* ok) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  *ok = true;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size()) *ok = false;
    } catch (const std::exception&) {
      *ok = false;
    }
  }
  return out;
}

std::string describe(const roadsim::Prepared& p, const roadsim::ExperimentConfig& c) {
  const ScenarioConfig& sc = p.scenario;
  std::ostringstream os;
  os << sc.name << ": ";
  for (std::size_t i = 0; i < sc.vehicle_types.size(); ++i) {
    const auto& d = sc.vehicle_types[i].driver;
    os << (i ? "; " : "") << sc.vehicle_types[i].name << " " << d.car_following << (d.human_driver ? "+HDM" : "") << "/"
       << d.lane_change;
  }
  char road[256];
  std::snprintf(road, sizeof road, "\n  road: %.1f km %s, %d+%d lanes, %.0f km/h; demand %.0f veh/h forward, %.0f backward",
                p.road.length_m / 1000.0, c.scenario_road ? "(the scenario's own)" : "straight",
                sc.road.lanes_forward, sc.road.lanes_backward, mps_to_kph(sc.road.speed_limit_mps),
                p.road.forward ? per_second_to_per_hour(sc.forward.flow_veh_per_s) : 0.0,
                p.road.backward ? per_second_to_per_hour(sc.backward.flow_veh_per_s) : 0.0);
  os << road << "\n  run: " << c.duration_s << " s (" << c.warmup_s << " s warm-up), step " << sc.step_s
     << " s, seed " << c.seed;
  return os.str();
}

bool write_csv(const std::string& path, const roadsim::ExperimentResult& r) {
  std::ofstream f(path);
  if (!f) return false;
  f << "detector_m,direction,start_s,end_s,vehicles,flow_veh_per_h,flow_per_lane_veh_per_h,time_mean_speed_kph,"
       "space_mean_speed_kph,density_veh_per_km,density_per_lane_veh_per_km\n";
  for (const auto& i : r.intervals) {
    f << i.detector_m << ',' << to_string(i.direction) << ',' << i.start_s << ',' << i.end_s << ',' << i.vehicles << ','
      << i.flow_veh_per_h << ',' << i.flow_per_lane_veh_per_h() << ',' << mps_to_kph(i.time_mean_speed_mps) << ','
      << mps_to_kph(i.space_mean_speed_mps) << ',' << i.density_veh_per_km << ','
      << i.density_per_lane_veh_per_km() << '\n';
  }
  return static_cast<bool>(f);
}

void print_detectors(const roadsim::Prepared& p, const roadsim::ExperimentResult& r) {
  for (double x : p.road.detectors_m) {
    for (Direction dir : {Direction::kForward, Direction::kBackward}) {
      std::size_t n = 0;
      double inv = 0.0;
      double seconds = 0.0;
      for (const auto& i : r.intervals) {
        if (i.detector_m != x || i.direction != dir) continue;
        n += i.vehicles;
        seconds += i.end_s - i.start_s;
        if (i.vehicles > 0) inv += static_cast<double>(i.vehicles) / i.space_mean_speed_mps;
      }
      if (seconds <= 0.0) continue;
      const double q = per_second_to_per_hour(static_cast<double>(n) / seconds);
      const double vs = inv > 0.0 ? static_cast<double>(n) / inv : 0.0;
      std::printf("  detector %.0f m %s: %zu vehicles, flow %.0f veh/h (%.0f per lane), space-mean speed %.1f km/h, "
                  "density %.1f veh/km, best flow over 5 intervals %.0f veh/h per lane\n",
                  x, to_string(dir), n, q, q / p.scenario.road.lanes(dir), mps_to_kph(vs),
                  vs > 0.0 ? q / mps_to_kph(vs) : 0.0,
                  roadsim::max_sustained_flow_per_lane(r.intervals, dir, x, 5));
    }
  }
}

int run(int argc, char** argv) {
  std::string scenario_path;
  std::string detectors;
  std::string csv;
  bool hdm_on = false;
  bool hdm_off = false;
  bool quiet = false;
  roadsim::ExperimentConfig c;
  cli::Args args("entourage-roadsim",
                 "Simulates a scenario's traffic on a whole road without a moving window (the micro region's driving "
                 "with sources at the road's ends) and reports detector flows, speeds and densities and the "
                 "simulation speed.");
  args.positional("SCENARIO", "scenario file (its vehicle types, drivers, demand and road)", &scenario_path);
  args.option("model", "NAME", "car-following model for every type: idm, modified_idm, gipps", &c.car_following);
  args.flag("hdm", "wrap the car-following model in the Human Driver Model", &hdm_on);
  args.flag("no-hdm", "without the Human Driver Model", &hdm_off);
  args.option("lane-change", "NAME", "lane-change model for every type: mobil, none, overtaking", &c.lane_change);
  args.option("flow", "VEH_PER_H", "forward demand (default: the scenario's)", &c.forward_flow_veh_per_h);
  args.option("backward-flow", "VEH_PER_H", "backward demand (default: the scenario's; 0 for none)",
              &c.backward_flow_veh_per_h);
  args.option("decision-interval", "S",
              "how often drivers weigh a discretionary lane change (default 0.5; 0: every step)",
              &c.decision_interval_s);
  args.option("lanes", "N", "lanes of the forward direction, and of the backward one on rural roads (on freeways at most N backward; default: the scenario's)", &c.lanes);
  args.option("length", "M", "length of the straight road (default 8000)", &c.length_m);
  args.flag("scenario-road", "simulate the scenario's own road (curves, zones, closures) instead", &c.scenario_road);
  args.option("duration", "S", "simulated time (default 1800)", &c.duration_s);
  args.option("warmup", "S", "time before detectors count (default 300)", &c.warmup_s);
  args.option("interval", "S", "detector aggregation interval (default 60)", &c.interval_s);
  args.option("detectors", "M,M,...", "detector positions along s (default: 3/4 along each simulated direction)", &detectors);
  args.option("seed", "N", "seed of the simulation's random stream (default 1)", &c.seed);
  args.option("csv", "FILE", "write every detector interval to FILE", &csv);
  args.flag("quiet", "no progress lines", &quiet);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  if (scenario_path.empty()) {
    std::cerr << "entourage-roadsim: a scenario file is required\n" << args.usage();
    return 2;
  }
  if (hdm_on && hdm_off) {
    std::cerr << "entourage-roadsim: --hdm and --no-hdm exclude each other\n";
    return 2;
  }
  c.human_driver = hdm_on ? 1 : hdm_off ? 0 : -1;
  if (!detectors.empty()) {
    bool ok = false;
    c.detectors_m = parse_list(detectors, &ok);
    if (!ok || c.detectors_m.empty()) {
      std::cerr << "entourage-roadsim: --detectors wants positions in metres separated by commas\n";
      return 2;
    }
  }
  const auto loaded = scenario::load_file(scenario_path);
  if (!loaded.ok()) {
    for (const auto& p : loaded.problems) std::cerr << p.to_string() << "\n";
    return 2;
  }
  const roadsim::Prepared prepared = roadsim::prepare(loaded.config, c);
  if (!prepared.ok()) {
    std::cerr << "entourage-roadsim: " << prepared.error << "\n";
    return 2;
  }
  std::cout << "entourage-roadsim: " << describe(prepared, c) << "\n";
  auto progress = +[](double t, const RoadSim& sim) {
    std::printf("  t %7.0f s  vehicles %5zu  waiting at the entrances %4zu\n", t, sim.vehicles(), sim.queued());
    std::fflush(stdout);
  };
  const auto t0 = std::chrono::steady_clock::now();
  const roadsim::ExperimentResult r = roadsim::run_experiment(prepared, c, quiet ? nullptr : progress);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "result:\n";
  print_detectors(prepared, r);
  std::printf("  mean speed on the road (space mean after the warm-up) %.1f km/h; mean trip speed %.1f km/h over %llu "
              "trips; at most %zu vehicles waiting to enter\n",
              mps_to_kph(r.mean_speed_mps), mps_to_kph(r.mean_trip_speed_mps),
              static_cast<unsigned long long>(r.counters.trips), r.max_queue);
  std::printf("  vehicles entered %llu, left %llu; lane changes %llu; overtakings %llu (%llu aborted); emergency "
              "vehicle-steps %llu\n",
              static_cast<unsigned long long>(r.counters.entered), static_cast<unsigned long long>(r.counters.left),
              static_cast<unsigned long long>(r.counters.lane_changes),
              static_cast<unsigned long long>(r.counters.overtakings_started),
              static_cast<unsigned long long>(r.counters.overtakings_aborted),
              static_cast<unsigned long long>(r.counters.emergency_decisions));
  std::printf("  vehicle updates %llu in %.2f s of wall time: %.0f updates/s (UPS), %.0f steps/s\n",
              static_cast<unsigned long long>(r.vehicle_updates), wall_s,
              wall_s > 0.0 ? static_cast<double>(r.vehicle_updates) / wall_s : 0.0,
              wall_s > 0.0 ? static_cast<double>(r.steps) / wall_s : 0.0);
  if (!csv.empty()) {
    if (!write_csv(csv, r)) {
      std::cerr << "entourage-roadsim: cannot write " << csv << "\n";
      return 1;
    }
    std::cout << "  detector intervals: " << csv << "\n";
  }
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) { return entourage::run(argc, argv); }
