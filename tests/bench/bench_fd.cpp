// entourage-bench-fd: fundamental diagrams of the car-following models on a two-lane freeway
// (paper V, Olstam & Tapani: the modified IDM gives a higher mean speed at the same flow and a
// higher capacity than IDM, more so with the Human Driver Model). For IDM and the modified IDM,
// each with and without HDM, the road simulation (traffic/road_sim.hpp) runs a sweep of demands on
// a straight road; a loop detector three quarters along it aggregates every interval into a point
// (flow, space-mean speed, density). Writes the points and a summary to CSV, draws them with
// gnuplot when it is installed (deploy/setup.sh --bench) and prints each model's capacity.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_util.hpp"
#include "cli/args.hpp"
#include "core/units.hpp"
#include "roadsim/core/road_experiment.hpp"
#include "scenario/loader.hpp"

namespace entourage {
namespace {

namespace fs = std::filesystem;

struct Variant {
  const char* label;
  const char* model;
  bool hdm;
};
constexpr Variant kVariants[] = {
    {"IDM", "idm", false},
    {"modified IDM", "modified_idm", false},
    {"IDM + HDM", "idm", true},
    {"modified IDM + HDM", "modified_idm", true},
};

// Intervals over which a sustained flow is taken as the capacity.
constexpr int kCapacityWindowIntervals = 5;

struct RunSummary {
  double demand_veh_per_h = 0.0;
  double flow_per_lane_veh_per_h = 0.0;  // at the detector, after the warm-up
  double space_mean_speed_kph = 0.0;
  double density_per_lane_veh_per_km = 0.0;
  double best_sustained_flow_per_lane = 0.0;
  double road_mean_speed_kph = 0.0;
  std::size_t max_queue = 0;
};

RunSummary summarise(double demand, const roadsim::ExperimentResult& r, int lanes) {
  RunSummary s;
  s.demand_veh_per_h = demand;
  std::size_t n = 0;
  double seconds = 0.0;
  double inverse_speeds = 0.0;
  for (const auto& i : r.intervals) {
    n += i.vehicles;
    seconds += i.end_s - i.start_s;
    if (i.vehicles > 0) inverse_speeds += static_cast<double>(i.vehicles) / i.space_mean_speed_mps;
  }
  const double q = seconds > 0.0 ? per_second_to_per_hour(static_cast<double>(n) / seconds) : 0.0;
  const double v = inverse_speeds > 0.0 ? static_cast<double>(n) / inverse_speeds : 0.0;
  s.flow_per_lane_veh_per_h = q / lanes;
  s.space_mean_speed_kph = mps_to_kph(v);
  s.density_per_lane_veh_per_km = v > 0.0 ? s.flow_per_lane_veh_per_h / s.space_mean_speed_kph : 0.0;
  if (!r.intervals.empty()) {
    s.best_sustained_flow_per_lane = roadsim::max_sustained_flow_per_lane(
        r.intervals, Direction::kForward, r.intervals.front().detector_m, kCapacityWindowIntervals);
  }
  s.road_mean_speed_kph = mps_to_kph(r.mean_speed_mps);
  s.max_queue = r.max_queue;
  return s;
}

std::vector<double> parse_list(const std::string& text, bool* ok) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  *ok = true;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size() || out.back() <= 0.0) *ok = false;
    } catch (const std::exception&) {
      *ok = false;
    }
  }
  return out;
}

// Mean speed at a flow (per lane) by linear interpolation between the demand levels below
// capacity (the free-flow branch); < 0 if the flow is outside them.
double speed_at_flow(const std::vector<RunSummary>& runs, double flow) {
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const RunSummary& a = runs[i - 1];
    const RunSummary& b = runs[i];
    if (b.max_queue > 0 && b.flow_per_lane_veh_per_h < a.flow_per_lane_veh_per_h) break;
    if (a.flow_per_lane_veh_per_h <= flow && flow <= b.flow_per_lane_veh_per_h &&
        b.flow_per_lane_veh_per_h > a.flow_per_lane_veh_per_h) {
      const double w = (flow - a.flow_per_lane_veh_per_h) / (b.flow_per_lane_veh_per_h - a.flow_per_lane_veh_per_h);
      return a.space_mean_speed_kph + w * (b.space_mean_speed_kph - a.space_mean_speed_kph);
    }
  }
  return -1.0;
}

int run(int argc, char** argv) {
  std::string scenario_path = std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/freeway.pbtxt";
  std::string out_dir = "bench-fd";
  std::string flows_text = "600,1200,1800,2400,2800,3200,3600,4000,4400,4800,5600";
  std::string gnuplot_script = std::string(ENTOURAGE_SOURCE_DIR) + "/tests/bench/fundamental_diagram.gp";
  double speed_flow_point = 1400.0;
  roadsim::ExperimentConfig c;
  c.duration_s = 1500.0;
  c.warmup_s = 300.0;
  c.interval_s = 60.0;
  c.length_m = 8000.0;
  c.lanes = 2;
  c.backward_flow_veh_per_h = 0.0;
  cli::Args args("entourage-bench-fd",
                 "Fundamental diagrams of IDM and the modified IDM, each with and without the Human Driver Model, on "
                 "a straight two-lane freeway: a sweep of demands through the road simulation, detector points to "
                 "CSV, a PNG drawn with gnuplot, and each model's capacity.");
  args.option("scenario", "FILE", "vehicle types, drivers and road (default scenarios/freeway.pbtxt)", &scenario_path);
  args.option("out", "DIR", "where the CSV files and the PNG go (default ./bench-fd)", &out_dir);
  args.option("flows", "VEH_PER_H,...", "demands of the sweep, whole cross-section", &flows_text);
  args.option("duration", "S", "simulated time per demand (default 1500)", &c.duration_s);
  args.option("warmup", "S", "time before the detector counts (default 300)", &c.warmup_s);
  args.option("interval", "S", "detector aggregation interval, one point each (default 60)", &c.interval_s);
  args.option("length", "M", "length of the road (default 8000; detector at 3/4)", &c.length_m);
  args.option("lanes", "N", "lanes (default 2)", &c.lanes);
  args.option("seed", "N", "seed of every run (default 1)", &c.seed);
  args.option("speed-at", "VEH_PER_H_PER_LANE", "flow at which mean speeds are compared (default 1400)",
              &speed_flow_point);
  args.option("gnuplot-script", "FILE", "the plot script (default tests/bench/fundamental_diagram.gp)",
              &gnuplot_script);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  bool ok = false;
  const std::vector<double> flows = parse_list(flows_text, &ok);
  if (!ok || flows.empty()) {
    std::cerr << "entourage-bench-fd: --flows wants positive demands in veh/h separated by commas\n";
    return 2;
  }
  const auto loaded = scenario::load_file(scenario_path);
  if (!loaded.ok()) {
    for (const auto& p : loaded.problems) std::cerr << p.to_string() << "\n";
    return 2;
  }
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  std::ofstream points(fs::path(out_dir) / "fd_points.csv");
  std::ofstream summary(fs::path(out_dir) / "fd_summary.csv");
  if (!points || !summary) {
    std::cerr << "entourage-bench-fd: cannot write to " << out_dir << "\n";
    return 1;
  }
  points << "model,demand_veh_per_h,start_s,flow_per_lane_veh_per_h,space_mean_speed_kph,density_per_lane_veh_per_km\n";
  summary << "model,demand_veh_per_h,flow_per_lane_veh_per_h,space_mean_speed_kph,density_per_lane_veh_per_km,"
             "best_5min_flow_per_lane_veh_per_h,road_mean_speed_kph,max_queue\n";
  std::printf("fundamental diagrams: %s vehicle types, %.1f km straight road, %d lanes, %.0f s per demand "
              "(%.0f s warm-up), %zu demands\n",
              loaded.config.name.c_str(), c.length_m / 1000.0, c.lanes, c.duration_s, c.warmup_s, flows.size());
  std::printf("  %-20s %14s %24s\n", "model", "capacity", "mean speed at the flow");
  std::printf("  %-20s %14s %24s\n", "", "veh/h per lane", "km/h");
  for (const Variant& variant : kVariants) {
    roadsim::ExperimentConfig vc = c;
    vc.car_following = variant.model;
    vc.human_driver = variant.hdm ? 1 : 0;
    std::vector<RunSummary> runs;
    double capacity = 0.0;
    for (double demand : flows) {
      vc.forward_flow_veh_per_h = demand;
      const roadsim::Prepared prepared = roadsim::prepare(loaded.config, vc);
      if (!prepared.ok()) {
        std::cerr << "entourage-bench-fd: " << prepared.error << "\n";
        return 2;
      }
      const roadsim::ExperimentResult r = roadsim::run_experiment(prepared, vc);
      const int lanes = prepared.scenario.road.lanes_forward;
      for (const auto& i : r.intervals) {
        if (i.vehicles == 0) continue;
        points << '"' << variant.label << "\"," << demand << ',' << i.start_s << ',' << i.flow_per_lane_veh_per_h()
               << ',' << mps_to_kph(i.space_mean_speed_mps) << ',' << i.density_per_lane_veh_per_km() << '\n';
      }
      const RunSummary s = summarise(demand, r, lanes);
      summary << '"' << variant.label << "\"," << demand << ',' << s.flow_per_lane_veh_per_h << ','
              << s.space_mean_speed_kph << ',' << s.density_per_lane_veh_per_km << ','
              << s.best_sustained_flow_per_lane << ',' << s.road_mean_speed_kph << ',' << s.max_queue << '\n';
      capacity = std::max(capacity, s.best_sustained_flow_per_lane);
      runs.push_back(s);
    }
    const double v = speed_at_flow(runs, speed_flow_point);
    char speed[32] = "-";
    if (v > 0.0) std::snprintf(speed, sizeof speed, "%.1f at %.0f", v, speed_flow_point);
    std::printf("  %-20s %14.0f %24s\n", variant.label, capacity, speed);
    std::fflush(stdout);
  }
  points.close();
  summary.close();
  std::printf("  points: %s\n  summary: %s\n", (fs::path(out_dir) / "fd_points.csv").c_str(),
              (fs::path(out_dir) / "fd_summary.csv").c_str());
  if (!bench::on_path("gnuplot")) {
    std::printf("  gnuplot is not installed (deploy/setup.sh --bench installs it): no PNG\n");
    return 0;
  }
  const std::string png = (fs::path(out_dir) / "fundamental_diagram.png").string();
  const std::string command = "gnuplot -e \"dir='" + out_dir + "'; png='" + png + "'\" '" + gnuplot_script + "'";
  if (std::system(command.c_str()) != 0) {
    std::cerr << "entourage-bench-fd: gnuplot failed: " << command << "\n";
    return 1;
  }
  std::printf("  diagram: %s\n", png.c_str());
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) { return entourage::run(argc, argv); }
