// entourage-bench-catchups: the ego stand-in's catch-ups in the window against those of the same
// driver on a whole road of the same demand.
//
// The window's validation (entourage verify) counts the vehicles that pass the ego (passive
// catch-ups) and that it passes (active) and compares them with the moving-observer prediction at
// the ego's speed (recording/summary.hpp). That prediction holds for an observer the stream passes
// freely. The ego is one of the stream's vehicles: it is held up in its lane, and the drivers it
// holds up gather behind it. What the window must reproduce is what that driver meets on a whole
// road, and this bench measures both:
//
//   whole road  the road simulation (traffic/road_sim.hpp) of the scenario's demand on a straight
//               road, every vehicle an observer over a stretch of it (crossings counted, the same
//               prediction integrated over its own speed history), and every n-th car given the
//               ego stand-in's driver (ego/core/ego_core.hpp): their figures are the reference;
//   window      drives of the window with every core in one process (window_cores.hpp, wired as
//               the DDS shells wire them), seeds 1..N, counted the same way.
//
// For both it prints, per hour, the vehicles crossing the points where the window's edges are
// (in and out, against the moving-observer rates), the mean number of vehicles of the ego's
// direction in each region and their space-mean speed, and the flow in the window (distance driven
// over length and time).
//
// With --probe-kph the window drives' ego is a transparent probe at that speed (scenario
// ego.transparent: nobody sees it, it sees nobody), the observer the moving-observer relations are
// made for: its catch-ups test the window's stream itself against the prediction; the whole road
// then carries transparent probes at the same speed instead of the ego stand-in's drivers (their
// crossings against the same prediction, and against the relations applied to the vehicles around
// them). The window's catch-ups are counted, observed and predicted, only while the whole window
// is on a stretch like the reference road the stream was observed on (straight, no speed zone,
// no overtaking restriction, no closure: window_catchups.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "cli/args.hpp"
#include "core/units.hpp"
#include "ego/core/ego_core.hpp"
#include "road/window.hpp"
#include "scenario/loader.hpp"
#include "traffic/observed_stream.hpp"
#include "traffic/road_sim.hpp"
#include "ordered_pool.hpp"
#include "window_catchups.hpp"
#include "window_cores.hpp"

namespace entourage {
namespace {

using bench::in_window;
using bench::observe_in_window;
using bench::observe_step;
using bench::relative_window;
using bench::Tally;
using bench::window_drive;
using bench::window_length_m;
using bench::with_probe;

struct Options {
  std::string scenario_path = std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/freeway.pbtxt";
  double length_m = 30000.0;
  double margin_m = 5000.0;
  double warmup_s = 1200.0;
  double duration_s = 7200.0;
  int seed = 1;
  int ego_every = 20;  // every n-th car entering the whole road drives like the ego stand-in
  int drives = 0;
  double drive_s = 1800.0;
  double probe_kph = -1.0;  // > 0: the window drives' ego is a transparent probe at this speed
  int jobs = 0;             // window drives on this many threads at once (0: one per logical CPU)
};

struct Observer {
  std::string group;
  bool ego_driver = false;
  Tally tally;
  std::unordered_map<VehicleId, double> near;  // ego drivers: vehicles near its window, relative position
};

std::string group_of(const ScenarioConfig& sc, const Vehicle& v) {
  const double kph = mps_to_kph(v.driver.desired_speed_mps());
  const int lo = static_cast<int>(kph / 10.0) * 10;
  char band[64];
  std::snprintf(band, sizeof band, "%s, wants %d-%d km/h", sc.vehicle_types[v.type_index].name.c_str(), lo, lo + 10);
  return band;
}

// A transparent probe on the whole road: a point at a set speed that nobody sees, started at the
// first margin every kProbeEvery_s after the warm-up and counting until the second margin; the
// vehicles of its direction within kProbeReach_m of it, ahead of it or not at the last step.
struct ProbeResult {
  Tally tally;
  double local_passive = 0.0;  // the moving-observer rates of the vehicles around it, integrated
  double local_active = 0.0;
};
struct RoadProbe {
  double s_m = 0.0;
  std::unordered_map<VehicleId, bool> ahead;
  ProbeResult result;
};
constexpr double kProbeEvery_s = 20.0;
constexpr double kProbeReach_m = 300.0;  // beyond the 4 m a step any relative speed moves

// The whole road: every forward vehicle an observer while it is between the margins (after the
// warm-up), crossings found by keeping the vehicles sorted by position (each swap of an insertion
// sort is one vehicle passing another). The ego drivers also track their window's edges. With a
// probe speed (> 0), transparent probes at that speed count their crossings too (`probes`), with
// the moving-observer relations applied to the vehicles around them at each step (local_*: the
// relations hold where the stream is what the probe meets, whatever the stream observed at
// startup predicts).
std::unordered_map<VehicleId, Observer> observe_whole_road(const ScenarioConfig& sc, const Options& o,
                                                           std::vector<ProbeResult>* probes = nullptr) {
  RoadSimConfig rc;
  rc.length_m = o.length_m;
  RoadSim sim(road_sim_scenario(sc, rc), Direction::kForward, rc, static_cast<std::uint64_t>(o.seed));
  const ObservedStream stream(sc, Direction::kForward, StreamObservation{},
                              observation_seed(generator_seed(static_cast<std::uint64_t>(o.seed)), Direction::kForward));
  const double dt = sc.step_s;
  const WindowBounds w = relative_window(sc.window);
  std::unordered_map<VehicleId, Observer> observers;
  std::vector<VehicleId> ego_drivers;  // those on the road
  std::vector<VehicleId> order;  // forward vehicles by increasing s
  std::unordered_map<VehicleId, const Vehicle*> on_road;
  const auto s_of = [&](VehicleId id) { return on_road.at(id)->s_m; };
  const auto counting = [&](double s) { return sim.time_s() >= o.warmup_s && s >= o.margin_m && s < o.length_m - o.margin_m; };
  int cars = 0;
  const double probe_mps = kph_to_mps(o.probe_kph);
  std::vector<RoadProbe> running;
  double next_probe_s = o.warmup_s;
  const auto steps = static_cast<long>((o.warmup_s + o.duration_s) / dt);
  for (long i = 0; i < steps; ++i) {
    sim.step();
    on_road.clear();
    for (const Vehicle& v : sim.fleet().vehicles()) {
      if (v.direction != Direction::kForward) continue;
      on_road[v.id] = &v;
      auto [it, fresh] = observers.try_emplace(v.id);
      if (fresh) {
        it->second.group = group_of(sc, v);
        order.insert(order.begin(), v.id);  // a new vehicle enters at the rear
        if (probes == nullptr && !sc.vehicle_types[v.type_index].keep_right && ++cars % o.ego_every == 0) {
          sim.redrive(v.id, ego::ego_driver(sc.ego, sim.environment(), static_cast<std::uint64_t>(cars)));
          it->second.group = "the ego stand-in's driver";
          it->second.ego_driver = true;
          ego_drivers.push_back(v.id);
        }
      }
      if (counting(v.s_m)) observe_step(it->second.tally, v.speed_mps, stream, dt);
    }
    const auto gone = [&](VehicleId id) { return !on_road.count(id); };
    order.erase(std::remove_if(order.begin(), order.end(), gone), order.end());
    ego_drivers.erase(std::remove_if(ego_drivers.begin(), ego_drivers.end(), gone), ego_drivers.end());
    for (std::size_t j = 1; j < order.size(); ++j) {
      for (std::size_t k = j; k > 0 && s_of(order[k]) < s_of(order[k - 1]); --k) {
        const VehicleId passed = order[k];      // was ahead, is now behind
        const VehicleId passer = order[k - 1];  // was behind, is now ahead
        if (counting(s_of(passed))) observers[passed].tally.passive += 1.0;
        if (counting(s_of(passer))) observers[passer].tally.active += 1.0;
        std::swap(order[k], order[k - 1]);
      }
    }
    if (probes != nullptr && probe_mps > 0.0) {
      if (sim.time_s() >= next_probe_s) {
        running.push_back({o.margin_m, {}, {}});
        next_probe_s += kProbeEvery_s;
      }
      for (RoadProbe& p : running) {
        p.s_m += probe_mps * dt;
        observe_step(p.result.tally, probe_mps, stream, dt);
        std::unordered_map<VehicleId, bool> now;
        auto first = std::lower_bound(order.begin(), order.end(), p.s_m - kProbeReach_m,
                                      [&](VehicleId v, double x) { return s_of(v) < x; });
        for (auto v = first; v != order.end() && s_of(*v) < p.s_m + kProbeReach_m; ++v) {
          const bool is_ahead = s_of(*v) >= p.s_m;
          const double rel_speed = on_road.at(*v)->speed_mps - probe_mps;
          (rel_speed > 0.0 ? p.result.local_passive : p.result.local_active) += std::abs(rel_speed) * dt / (2.0 * kProbeReach_m);
          now[*v] = is_ahead;
          const auto b = p.ahead.find(*v);
          if (b == p.ahead.end()) continue;
          if (!b->second && is_ahead) p.result.tally.passive += 1.0;
          if (b->second && !is_ahead) p.result.tally.active += 1.0;
        }
        p.ahead = std::move(now);
      }
      const auto done = [&](const RoadProbe& p) { return p.s_m >= o.length_m - o.margin_m; };
      for (const RoadProbe& p : running) {
        if (done(p)) probes->push_back(p.result);
      }
      running.erase(std::remove_if(running.begin(), running.end(), done), running.end());
    }
    for (const VehicleId id : ego_drivers) {
      Observer& ob = observers[id];
      const double s_ego = s_of(id);
      const bool count = counting(s_ego);
      std::unordered_map<VehicleId, double> now;
      auto first = std::lower_bound(order.begin(), order.end(), s_ego + w.rear_edge_m - 200.0,
                                    [&](VehicleId v, double x) { return s_of(v) < x; });
      for (auto v = first; v != order.end() && s_of(*v) < s_ego + w.front_edge_m + 200.0; ++v) {
        if (*v == id) continue;
        const double rel = s_of(*v) - s_ego;
        now[*v] = rel;
        auto b = ob.near.find(*v);
        if (count) observe_in_window(ob.tally, b == ob.near.end() ? std::nan("") : b->second, rel, on_road.at(*v)->speed_mps, w, dt);
      }
      ob.near = std::move(now);
    }
  }
  return observers;
}

// Ratio of a sum of counts to a sum of predictions, with its standard error from the spread of
// the units (drives or observers) about the pooled ratio.
struct Ratio {
  double value = 0.0;
  double error = 0.0;
};
Ratio pooled_ratio(const std::vector<std::pair<double, double>>& observed_predicted) {
  double o = 0.0;
  double p = 0.0;
  for (const auto& [oi, pi] : observed_predicted) {
    o += oi;
    p += pi;
  }
  Ratio r;
  if (p <= 0.0) return r;
  r.value = o / p;
  double squares = 0.0;
  for (const auto& [oi, pi] : observed_predicted) squares += (oi - r.value * pi) * (oi - r.value * pi);
  const double n = static_cast<double>(observed_predicted.size());
  r.error = n > 1.0 ? std::sqrt(squares * n / (n - 1.0)) / p : 0.0;
  return r;
}

struct Pooled {
  Tally total;
  std::vector<std::pair<double, double>> passive;  // per unit: observed, predicted
  std::vector<std::pair<double, double>> active;
  void add(const Tally& t) {
    total.add(t);
    passive.emplace_back(t.passive, t.predicted_passive);
    active.emplace_back(t.active, t.predicted_active);
  }
};

void print_group(const std::string& label, const Tally& t, std::size_t observers) {
  const double km = t.distance_m / 1000.0;
  if (km <= 0.0) return;
  std::printf("  %-28s %6zu %8.0f  passive %5.2f/km of %5.2f (%.2f)  active %5.2f/km of %5.2f (%.2f)\n", label.c_str(),
              observers, km, t.passive / km, t.predicted_passive / km,
              t.predicted_passive > 0.0 ? t.passive / t.predicted_passive : 0.0, t.active / km,
              t.predicted_active / km, t.predicted_active > 0.0 ? t.active / t.predicted_active : 0.0);
}

// The pooled figures of the ego stand-in's driver (on the whole road or in the window).
void print_ego(const char* label, const Pooled& p, const ScenarioConfig& sc, const ObservedStream& stream) {
  const double demand_veh_per_s = stream.flow_veh_per_s();
  const double density_per_m = stream.density_per_m();
  const double mean_speed_mps = stream.mean_speed_mps();
  const Tally& t = p.total;
  if (t.observed_s <= 0.0) return;
  const Ratio passive = pooled_ratio(p.passive);
  const Ratio active = pooled_ratio(p.active);
  const WindowConfig& w = sc.window;
  const double h = t.observed_s / 3600.0;
  const double counted_h = std::max(t.counted_s, 1e-9) / 3600.0;  // the rates as predicted where counted
  std::printf("%s: %zu, %.0f km at %.1f km/h\n", label, p.passive.size(), t.distance_m / 1000.0,
              mps_to_kph(t.distance_m / t.observed_s));
  std::printf("  catch-ups against the moving-observer prediction: passive %.2f +- %.2f, active %.2f +- %.2f (counted in "
              "%.0f %% of the time: the window on a stretch like the reference road)\n",
              passive.value, passive.error, active.value, active.error, 100.0 * t.counted_s / t.observed_s);
  std::printf("  per hour at the rear edge: in %.1f, out %.1f (moving-observer rate %.1f); at the front edge: in "
              "%.1f, out %.1f (rate %.1f)\n",
              t.rear_in / h, t.rear_out / h, t.predicted_passive / counted_h, t.front_in / h, t.front_out / h,
              t.predicted_active / counted_h);
  const double inner = (t.vehicle_seconds - t.rear_outer_seconds - t.front_outer_seconds) / t.observed_s;
  std::printf("  vehicles of its direction in the window: %.1f (outer behind %.1f, inner %.1f, outer ahead %.1f; the "
              "stream's density gives %.1f, %.1f, %.1f)\n",
              t.vehicle_seconds / t.observed_s, t.rear_outer_seconds / t.observed_s, inner,
              t.front_outer_seconds / t.observed_s, density_per_m * w.outer_behind_m,
              density_per_m * (w.inner_behind_m + w.inner_ahead_m), density_per_m * w.outer_ahead_m);
  const auto kph = [](double metres, double seconds) { return seconds > 0.0 ? mps_to_kph(metres / seconds) : 0.0; };
  const double inner_seconds = t.vehicle_seconds - t.rear_outer_seconds - t.front_outer_seconds;
  std::printf("  their space-mean speed: %.1f km/h (outer behind %.1f, inner %.1f, outer ahead %.1f; the stream's %.1f)\n",
              kph(t.vehicle_metres, t.vehicle_seconds), kph(t.rear_outer_metres, t.rear_outer_seconds),
              kph(t.vehicle_metres - t.rear_outer_metres - t.front_outer_metres, inner_seconds),
              kph(t.front_outer_metres, t.front_outer_seconds), mps_to_kph(mean_speed_mps));
  const double flow = t.vehicle_metres / (window_length_m(w) * t.observed_s);
  std::printf("  flow of its direction in the window: %.0f veh/h, %+.1f %% of the demand\n", per_second_to_per_hour(flow),
              100.0 * (flow / demand_veh_per_s - 1.0));
}

int check_options(const Options& o) {
  const auto bad = [](const char* what) {
    std::fprintf(stderr, "entourage-bench-catchups: %s\n", what);
    return 2;
  };
  if (!(o.length_m > 2.0 * o.margin_m + 1000.0) || !(o.margin_m >= 0.0)) {
    return bad("--length must exceed twice --margin by a kilometre at least, --margin must be >= 0");
  }
  if (!(o.warmup_s >= 0.0) || !(o.duration_s > 0.0)) return bad("--warmup must be >= 0 and --duration > 0 seconds");
  if (o.ego_every < 1) return bad("--ego-every must be >= 1");
  if (o.jobs < 0 || o.jobs > 1024) return bad("--jobs must be from 0 (one per logical CPU) to 1024");
  if (o.drives < 0 || !(o.drive_s > 0.0)) return bad("--drives must be >= 0 and --drive-duration > 0 seconds");
  if (o.probe_kph != -1.0 && !(o.probe_kph > 0.0 && o.probe_kph <= 250.0)) {
    return bad("--probe-kph must be in (0, 250] km/h");
  }
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) {
  using namespace entourage;
  Options o;
  cli::Args args("entourage-bench-catchups",
                 "The ego stand-in's catch-ups in the window against those of the same driver on a whole road of the "
                 "same demand (no window), both against the moving-observer prediction; with the crossings at the "
                 "window's edges, the vehicles in each region and the flow in the window.");
  args.option("scenario", "FILE", "demand, drivers, ego and window (default scenarios/freeway.pbtxt)", &o.scenario_path);
  args.option("length", "M", "whole road: length of the straight road (default 30000)", &o.length_m);
  args.option("margin", "M", "whole road: observers count from this far past the entrance to this far before the end "
              "(default 5000)", &o.margin_m);
  args.option("warmup", "S", "whole road: time before counting (default 1200)", &o.warmup_s);
  args.option("duration", "S", "whole road: counted time (default 7200)", &o.duration_s);
  args.option("seed", "N", "whole road: seed (default 1)", &o.seed);
  args.option("ego-every", "N", "whole road: every N-th car drives like the ego stand-in (default 20)", &o.ego_every);
  args.option("drives", "N", "window drives, seeds 1..N (default 0)", &o.drives);
  args.option("jobs", "N", "window drives on N threads at once (default 0: one per logical CPU); the output is the "
              "same", &o.jobs);
  args.option("drive-duration", "S", "simulated time of each window drive (default 1800)", &o.drive_s);
  args.option("probe-kph", "KPH", "the window drives' ego is a transparent probe (scenario ego.transparent) at this "
              "speed, and the whole road carries transparent probes at it instead of the ego stand-in's drivers "
              "(default: the scenario's ego stand-in)", &o.probe_kph);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  if (const int rc = check_options(o)) return rc;
  const auto loaded = scenario::load_file(o.scenario_path);
  if (!loaded.ok()) {
    for (const auto& p : loaded.problems) std::fprintf(stderr, "%s\n", p.to_string().c_str());
    return 2;
  }
  const ScenarioConfig& sc = loaded.config;
  const ObservedStream stream(sc, Direction::kForward, StreamObservation{},
                              observation_seed(generator_seed(static_cast<std::uint64_t>(o.seed)), Direction::kForward));

  Pooled road_egos;
  if (o.probe_kph < 0.0) {
    std::printf("whole road: %s demand, %.0f km straight road, seed %d, %.0f s counted after %.0f s, observers between "
                "%.0f and %.0f m, every %d-th car the ego stand-in's driver\n",
                sc.name.c_str(), o.length_m / 1000.0, o.seed, o.duration_s, o.warmup_s, o.margin_m,
                o.length_m - o.margin_m, o.ego_every);
    std::printf("  %-28s %6s %8s  per km of the observer's travel, observed of predicted (ratio)\n", "observer", "n", "km");
    const auto observers = observe_whole_road(sc, o);
    std::map<std::string, std::pair<Tally, std::size_t>> groups;
    for (const auto& [id, ob] : observers) {
      if (ob.tally.observed_s <= 0.0) continue;
      auto& g = groups[ob.group];
      g.first.add(ob.tally);
      ++g.second;
      if (ob.ego_driver) road_egos.add(ob.tally);
    }
    for (const auto& [label, g] : groups) print_group(label, g.first, g.second);
    print_ego("the ego stand-in's drivers on the whole road", road_egos, sc, stream);
  }
  if (o.probe_kph > 0.0) {
    std::printf("whole road: %s demand, %.0f km straight road, seed %d, %.0f s counted after %.0f s: transparent "
                "probes at %.0f km/h, one every %.0f s, each from %.0f to %.0f m\n",
                sc.name.c_str(), o.length_m / 1000.0, o.seed, o.duration_s, o.warmup_s, o.probe_kph, kProbeEvery_s,
                o.margin_m, o.length_m - o.margin_m);
    std::vector<ProbeResult> probes;
    observe_whole_road(sc, o, &probes);
    Pooled pooled;
    double local_passive = 0.0;
    double local_active = 0.0;
    for (const ProbeResult& r : probes) {
      pooled.add(r.tally);
      local_passive += r.local_passive;
      local_active += r.local_active;
    }
    const Ratio p = pooled_ratio(pooled.passive);
    const Ratio a = pooled_ratio(pooled.active);
    std::printf("  %zu probes, %.0f km: passive %.0f of %.1f predicted (%.2f +- %.2f), active %.0f of %.1f (%.2f +- %.2f)\n",
                probes.size(), pooled.total.distance_m / 1000.0, pooled.total.passive, pooled.total.predicted_passive,
                p.value, p.error, pooled.total.active, pooled.total.predicted_active, a.value, a.error);
    std::printf("  the relations over the vehicles around the probes (within %.0f m) give passive %.1f, active %.1f\n",
                kProbeReach_m, local_passive, local_active);
  }
  if (o.drives == 0) return 0;
  const ScenarioConfig drive_sc = o.probe_kph > 0.0 ? with_probe(sc, o.probe_kph) : sc;
  if (o.probe_kph > 0.0) {
    std::printf("window drives of a transparent probe at %.0f km/h (%s demand), against the moving-observer "
                "prediction\n", o.probe_kph, sc.name.c_str());
  }

  Pooled window;
  std::vector<Tally> tallies(static_cast<std::size_t>(o.drives));
  const auto drive = [&](std::size_t i) {
    tallies[i] = window_drive(drive_sc, static_cast<std::uint64_t>(i + 1), o.drive_s);
  };
  const auto take = [&](std::size_t i) {
    const int d = static_cast<int>(i) + 1;
    const Tally& t = tallies[i];
    window.add(t);
    std::printf("  window drive, seed %3d: %5.1f km at %5.1f km/h, passive %4.0f of %6.1f, active %4.0f of %6.1f\n", d,
                t.distance_m / 1000.0, mps_to_kph(t.distance_m / std::max(1.0, t.observed_s)), t.passive,
                t.predicted_passive, t.active, t.predicted_active);
    std::fflush(stdout);
  };
  bench::run_in_order(tallies.size(), bench::pool_threads(o.jobs, tallies.size()), drive, take);
  print_ego(o.probe_kph > 0.0 ? "the probe's window drives" : "the ego stand-in's window drives", window, sc, stream);
  const ObservedStream oncoming(sc, Direction::kBackward, StreamObservation{},
                                observation_seed(generator_seed(static_cast<std::uint64_t>(o.seed)), Direction::kBackward));
  const Tally& wt = window.total;
  if (wt.observed_s > 0.0 && oncoming.flow_veh_per_s() > 0.0) {
    const double flow = wt.oncoming_metres / (window_length_m(sc.window) * wt.observed_s);
    std::printf("  oncoming: met %.0f of %.1f predicted (%.3f); flow in the window %.0f veh/h, %+.1f %% of the demand\n",
                wt.met, wt.predicted_met, wt.met / wt.predicted_met, per_second_to_per_hour(flow),
                100.0 * (flow / oncoming.flow_veh_per_s() - 1.0));
  }
  const Ratio road_p = pooled_ratio(road_egos.passive);
  const Ratio road_a = pooled_ratio(road_egos.active);
  const Ratio win_p = pooled_ratio(window.passive);
  const Ratio win_a = pooled_ratio(window.active);
  if (road_p.value > 0.0 && road_a.value > 0.0) {
    std::printf("window against the whole road: passive %.2f, active %.2f\n", win_p.value / road_p.value,
                win_a.value / road_a.value);
  }
  return 0;
}
