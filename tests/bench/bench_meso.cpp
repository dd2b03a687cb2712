// entourage-bench-meso: what the mesoscopic outer regions save (issue 4, "The moving window":
// the same window run all-micro against micro inside and meso outside; a mesoscopic model at
// least ten times cheaper than micro per vehicle per step).
//
// For each scenario, the pure cores run in one process, in lockstep, with the scenario's ego
// stand-in (window_cores.hpp), in two configurations of the same window:
//   all-micro   the inner region reaches the window's edges (outer regions of length 0; meso
//               only passes on, for one step, what leaves the window, as the handoffs require)
//   split       the scenario's window: micro inside, meso in the outer regions
// Every step's input is kept, and each core then replays the whole run alone from a fresh copy,
// several times, alternating between the configurations; the CPU time of its thread (not
// wall-clock time) over its fastest replay, divided by the steps, is its cost per step. A first,
// untimed replay checks that each core computes exactly what it did in the live run (the
// fingerprints printed). Vehicle-steps: the vehicles each core moved.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/args.hpp"
#include "scenario/loader.hpp"
#include "traffic/carried_states.hpp"
#include "window_cores.hpp"

namespace entourage {
namespace {

enum CoreKind : std::size_t { kGeneratorCore = 0, kMicroCore = 1, kMesoCore = 2 };
constexpr std::size_t kCores = 3;

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// A fingerprint of what a core published (FNV-1a over ids, positions, speeds, handoff targets).
class Digest {
 public:
  void add(std::uint64_t x) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (x >> (8 * i)) & 0xFFU;
      hash_ *= 0x100000001B3ULL;
    }
  }
  void add(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    add(bits);
  }
  void add(const StepOutput& out) {
    for (const VehicleReport& r : out.states) {
      add(static_cast<std::uint64_t>(r.id));
      add(r.s_m);
      add(r.speed_mps);
      add(static_cast<std::uint64_t>(r.target_lane));
    }
    for (const Handoff& h : out.handoffs) {
      add(static_cast<std::uint64_t>(h.vehicle.id));
      add(static_cast<std::uint64_t>(h.to_role) << 8U | static_cast<std::uint64_t>(h.to_region));
    }
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ULL;
};

// One configuration run live: every step's input, and what each core did with it.
struct LiveRun {
  std::vector<StepInput> inputs;
  std::array<std::uint64_t, kCores> vehicle_steps{};
  std::array<std::uint64_t, kCores> digest{};
  std::array<std::uint64_t, kCores> published{};  // vehicle states, over the run
  std::array<double, kCores> live_cpu_s{};  // timed step by step, the cores interleaved
  meso::Counters meso;                      // meso's own counts over the run
  std::uint64_t meso_not_carried = 0;       // meso states a reader could not carry forward (carried_states.hpp)
  double select_cpu_s = 0.0;                // finding them (SparseStates::select), over the run
  bool reached_road_end = false;
};

// Vehicles a region core moved in its last step: those it still owns and those it handed on.
template <class Core>
std::uint64_t moved(const Core& core, const StepOutput& out) {
  return core.fleet().size() + out.handoffs.size();
}

template <class Core>
StepOutput timed_step(Core& core, const StepInput& in, double* cpu_s) {
  const double t0 = thread_cpu_s();
  StepOutput out = core.step(in);
  *cpu_s += thread_cpu_s() - t0;
  return out;
}

LiveRun run_live(const ScenarioConfig& sc, std::uint64_t seed, Step last_step,
                 std::optional<generator::GeneratorCore>* pristine) {
  LiveRun run;
  bench::WindowCores cores(sc, seed);
  pristine->emplace(cores.generator());  // before its first step: the replays start from it
  std::array<Digest, kCores> digests;
  SparseStates sparse(sc.step_s);
  run.inputs.reserve(static_cast<std::size_t>(last_step) + 1);
  for (Step k = 0; k <= last_step; ++k) {
    StepInput in = cores.next_input();
    bench::StepOutputs out;
    out.generator = timed_step(cores.generator(), in, &run.live_cpu_s[kGeneratorCore]);
    out.micro = timed_step(cores.micro(), in, &run.live_cpu_s[kMicroCore]);
    out.meso = timed_step(cores.meso(), in, &run.live_cpu_s[kMesoCore]);
    run.vehicle_steps[kGeneratorCore] += out.generator.states.size();  // the front zone
    run.vehicle_steps[kMicroCore] += moved(cores.micro(), out.micro);
    run.vehicle_steps[kMesoCore] += moved(cores.meso(), out.meso);
    digests[kGeneratorCore].add(out.generator);
    digests[kMicroCore].add(out.micro);
    digests[kMesoCore].add(out.meso);
    run.published[kGeneratorCore] += out.generator.states.size();
    run.published[kMicroCore] += out.micro.states.size();
    run.published[kMesoCore] += out.meso.states.size();
    const double t0 = thread_cpu_s();
    run.meso_not_carried += sparse.select(out.meso.states).states.size();
    run.select_cpu_s += thread_cpu_s() - t0;
    cores.publish(in, out);
    run.inputs.push_back(std::move(in));
    if (cores.at_road_end()) {
      run.reached_road_end = true;
      break;
    }
  }
  for (std::size_t c = 0; c < kCores; ++c) run.digest[c] = digests[c].value();
  run.meso = cores.meso().counters();
  return run;
}

// The core's digest over a replay of the whole run from `core` (a fresh copy).
template <class Core>
std::uint64_t replay_digest(Core core, const std::vector<StepInput>& inputs) {
  Digest d;
  for (const StepInput& in : inputs) d.add(core.step(in));
  return d.value();
}

// The core thread's CPU time over a replay of the whole run from `core` (a fresh copy); the
// vehicle states it published go to `published` (so that the work is observable, and checked).
template <class Core>
double replay_cpu_s(Core core, const std::vector<StepInput>& inputs, std::uint64_t* published) {
  std::uint64_t n = 0;
  const double t0 = thread_cpu_s();
  for (const StepInput& in : inputs) n += core.step(in).states.size();
  const double t = thread_cpu_s() - t0;
  *published = n;
  return t;
}

struct Figures {
  std::uint64_t steps = 0;
  double seconds_per_step = 0.1;
  std::array<double, kCores> cpu_s{};     // the fastest replay, whole run
  std::array<double, kCores> live_cpu_s{};
  std::array<std::uint64_t, kCores> vehicle_steps{};
  std::array<std::uint64_t, kCores> digest{};
  meso::Counters meso;
  std::uint64_t meso_not_carried = 0;  // of meso's states, those a reader could not carry forward
  std::uint64_t meso_published = 0;    // meso's states, over the run
  double select_cpu_s = 0.0;
  bool reached_road_end = false;

  double us_per_step(std::size_t c) const { return 1e6 * cpu_s[c] / static_cast<double>(steps); }
  double total_us_per_step() const { return us_per_step(kGeneratorCore) + us_per_step(kMicroCore) + us_per_step(kMesoCore); }
  double vehicles_per_step(std::size_t c) const { return static_cast<double>(vehicle_steps[c]) / static_cast<double>(steps); }
  double us_per_vehicle_step(std::size_t c) const {
    return vehicle_steps[c] > 0 ? 1e6 * cpu_s[c] / static_cast<double>(vehicle_steps[c]) : 0.0;
  }
  double live_us_per_step(std::size_t c) const { return 1e6 * live_cpu_s[c] / static_cast<double>(steps); }
};

// One configuration of the window: its live run, the generator as it was before its first step
// (the replays start from copies of it) and the figures.
struct Configuration {
  ScenarioConfig scenario;
  std::optional<generator::GeneratorCore> generator;
  LiveRun run;
  Figures figures;
};

Configuration run_configuration(const ScenarioConfig& sc, std::uint64_t seed, Step last_step) {
  Configuration c;
  c.scenario = sc;
  c.run = run_live(sc, seed, last_step, &c.generator);
  Figures& f = c.figures;
  f.steps = c.run.inputs.size();
  f.seconds_per_step = sc.step_s;
  f.live_cpu_s = c.run.live_cpu_s;
  f.vehicle_steps = c.run.vehicle_steps;
  f.digest = c.run.digest;
  f.reached_road_end = c.run.reached_road_end;
  f.meso = c.run.meso;
  f.meso_not_carried = c.run.meso_not_carried;
  f.meso_published = c.run.published[kMesoCore];
  f.select_cpu_s = c.run.select_cpu_s;
  return c;
}

// Does every core's replay compute exactly what the live run did? (Also warms the caches.)
bool replays_match(const Configuration& c) {
  const LiveRun& run = c.run;
  return replay_digest(*c.generator, run.inputs) == run.digest[kGeneratorCore] &&
         replay_digest(micro::MicroCore(c.scenario, bench::kMicroService), run.inputs) == run.digest[kMicroCore] &&
         replay_digest(meso::MesoCore(c.scenario, bench::kMesoService), run.inputs) == run.digest[kMesoCore];
}

// Replays every core once more; each core keeps its least CPU time (the replay least disturbed
// by other processes on the host). False if a replay published other than the live run.
bool time_replays(Configuration& c, bool first) {
  const LiveRun& run = c.run;
  std::array<double, kCores> t{};
  std::array<std::uint64_t, kCores> published{};
  t[kGeneratorCore] = replay_cpu_s(*c.generator, run.inputs, &published[kGeneratorCore]);
  t[kMicroCore] = replay_cpu_s(micro::MicroCore(c.scenario, bench::kMicroService), run.inputs, &published[kMicroCore]);
  t[kMesoCore] = replay_cpu_s(meso::MesoCore(c.scenario, bench::kMesoService), run.inputs, &published[kMesoCore]);
  for (std::size_t k = 0; k < kCores; ++k) {
    if (published[k] != run.published[k]) return false;
    c.figures.cpu_s[k] = first ? t[k] : std::min(c.figures.cpu_s[k], t[k]);
  }
  return true;
}

// The same window with the inner region reaching its edges. (Outer regions of length 0 are below
// what scenario validation accepts; the cores take them: meso then only passes leaving vehicles on.)
ScenarioConfig all_micro(ScenarioConfig sc) {
  WindowConfig& w = sc.window;
  w.inner_ahead_m += w.outer_ahead_m;
  w.inner_behind_m += w.outer_behind_m;
  w.outer_ahead_m = 0.0;
  w.outer_behind_m = 0.0;
  return sc;
}

void print_row(const char* label, const Figures& f) {
  std::printf("  %-22s %8.1f %8.1f %9.1f %8.1f   %7.1f %7.1f %10.1f\n", label, f.us_per_step(kMicroCore),
              f.us_per_step(kMesoCore), f.us_per_step(kGeneratorCore), f.total_us_per_step(),
              f.vehicles_per_step(kMicroCore), f.vehicles_per_step(kMesoCore), f.vehicles_per_step(kGeneratorCore));
}

// A core's cost per step as fixed + marginal * vehicles, through its two configurations.
struct CostLine {
  double fixed_us = 0.0;
  double marginal_us = 0.0;
};

CostLine cost_line(const Figures& a, const Figures& b, std::size_t c) {
  const double dn = a.vehicles_per_step(c) - b.vehicles_per_step(c);
  if (std::abs(dn) < 1e-9) return {};
  CostLine l;
  l.marginal_us = (a.us_per_step(c) - b.us_per_step(c)) / dn;
  l.fixed_us = b.us_per_step(c) - l.marginal_us * b.vehicles_per_step(c);
  return l;
}

// The table of both configurations and the saving.
void print_table(const Figures& micro_only, const Figures& split) {
  std::printf("  %-22s %s   %s\n", "", "--------- CPU per step, us ---------", "--- vehicles per step ----");
  std::printf("  %-22s %8s %8s %9s %8s   %7s %7s %10s\n", "configuration", "micro", "meso", "generator", "total",
              "micro", "meso", "front zone");
  print_row("all-micro", micro_only);
  print_row("micro inside, meso out", split);
  const double a = micro_only.total_us_per_step();
  const double b = split.total_us_per_step();
  std::printf("  saving: %.1f %% of the CPU per step (all-micro %.1f us, split %.1f us: %.2f times)\n",
              100.0 * (a - b) / a, a, b, a / b);
}

// Meso against micro per vehicle-step, and as fixed + marginal costs.
void print_vehicle_costs(const Figures& micro_only, const Figures& split) {
  const double micro_cost = split.us_per_vehicle_step(kMicroCore);
  const double meso_cost = split.us_per_vehicle_step(kMesoCore);
  std::printf("  per vehicle-step: micro %.3f us (all-micro %.3f us), meso %.3f us: meso %.1f times cheaper "
              "(issue 4 asks at least 10)\n",
              micro_cost, micro_only.us_per_vehicle_step(kMicroCore), meso_cost,
              meso_cost > 0.0 ? micro_cost / meso_cost : 0.0);
  const meso::Counters& m = split.meso;
  std::printf("  meso planned at %.1f %% of the steps (every %.1f s on average), %.3f plans per vehicle-step "
              "(%.1f %% of them for alert vehicles between updates); a pass under way at %.1f %% of the steps "
              "(%llu passes)\n",
              m.steps > 0 ? 100.0 * static_cast<double>(m.planning_steps) / static_cast<double>(m.steps) : 0.0,
              m.planning_steps > 0 ? split.seconds_per_step * static_cast<double>(m.steps) /
                                         static_cast<double>(m.planning_steps)
                                   : 0.0,
              split.vehicle_steps[kMesoCore] > 0
                  ? static_cast<double>(m.plans) / static_cast<double>(split.vehicle_steps[kMesoCore])
                  : 0.0,
              m.plans > 0 ? 100.0 * static_cast<double>(m.alert_plans) / static_cast<double>(m.plans) : 0.0,
              m.steps > 0 ? 100.0 * static_cast<double>(m.overtaking_steps) / static_cast<double>(m.steps) : 0.0,
              static_cast<unsigned long long>(m.overtakings_started));
  std::printf("  meso states a reader could not carry forward from the last it got (traffic/carried_states.hpp): "
              "%.1f %% (%.3f per vehicle-step); finding them %.3f us per state\n",
              split.meso_published > 0
                  ? 100.0 * static_cast<double>(split.meso_not_carried) / static_cast<double>(split.meso_published)
                  : 0.0,
              split.vehicle_steps[kMesoCore] > 0 ? static_cast<double>(split.meso_not_carried) /
                                                       static_cast<double>(split.vehicle_steps[kMesoCore])
                                                 : 0.0,
              split.meso_published > 0 ? 1e6 * split.select_cpu_s / static_cast<double>(split.meso_published) : 0.0);
  const CostLine micro_line = cost_line(micro_only, split, kMicroCore);
  const CostLine meso_line = cost_line(split, micro_only, kMesoCore);
  std::printf("  as fixed + marginal (through both configurations): micro %.2f us per step + %.3f us per vehicle, "
              "meso %.2f us + %.3f us: marginally meso %.1f times cheaper\n",
              micro_line.fixed_us, micro_line.marginal_us, meso_line.fixed_us, meso_line.marginal_us,
              meso_line.marginal_us > 0.0 ? micro_line.marginal_us / meso_line.marginal_us : 0.0);
}

// The live run's own timings, the fingerprints, and whether the runs were cut short.
void print_live_and_checks(const Figures& micro_only, const Figures& split) {
  std::printf("  live run, cores interleaved and timed step by step (us per step, all-micro / split): micro %.1f / "
              "%.1f, meso %.1f / %.1f, generator %.1f / %.1f\n",
              micro_only.live_us_per_step(kMicroCore), split.live_us_per_step(kMicroCore),
              micro_only.live_us_per_step(kMesoCore), split.live_us_per_step(kMesoCore),
              micro_only.live_us_per_step(kGeneratorCore), split.live_us_per_step(kGeneratorCore));
  std::printf("  fingerprints of what the cores published (generator micro meso): all-micro %016llx %016llx "
              "%016llx, split %016llx %016llx %016llx\n",
              static_cast<unsigned long long>(micro_only.digest[kGeneratorCore]),
              static_cast<unsigned long long>(micro_only.digest[kMicroCore]),
              static_cast<unsigned long long>(micro_only.digest[kMesoCore]),
              static_cast<unsigned long long>(split.digest[kGeneratorCore]),
              static_cast<unsigned long long>(split.digest[kMicroCore]),
              static_cast<unsigned long long>(split.digest[kMesoCore]));
  if (micro_only.reached_road_end || split.reached_road_end) {
    std::printf("  (the ego reached the end of the road: the runs ended early)\n");
  }
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon != std::string::npos) return line.substr(std::min(line.size(), colon + 2));
  }
  return "unknown CPU";
}

// A scenario's path as printed: relative to the source tree when it lies in it.
std::string shown_path(const std::string& path) {
  const std::string root = std::string(ENTOURAGE_SOURCE_DIR) + "/";
  return path.rfind(root, 0) == 0 ? path.substr(root.size()) : path;
}

// Benchmarks one scenario; false if a replay diverged.
bool bench_scenario(const std::string& path, const ScenarioConfig& sc, std::uint64_t seed_option, double duration_s,
                    int repeat) {
  const std::uint64_t seed = seed_option != 0 ? seed_option : sc.seed;
  const Step last_step = static_cast<Step>(std::llround(duration_s / sc.step_s));
  const WindowConfig& w = sc.window;
  std::printf("\n%s (%s), seed %llu: window %.0f m, inner %.0f m ahead and %.0f m behind the ego, outer %.0f m "
              "ahead and %.0f m behind that\n",
              sc.name.c_str(), shown_path(path).c_str(), static_cast<unsigned long long>(seed),
              w.inner_ahead_m + w.inner_behind_m + w.outer_ahead_m + w.outer_behind_m, w.inner_ahead_m,
              w.inner_behind_m, w.outer_ahead_m, w.outer_behind_m);
  std::fflush(stdout);
  // The replays alternate between the configurations, so that both meet the same load on the host.
  std::array<Configuration, 2> configurations{run_configuration(all_micro(sc), seed, last_step),
                                              run_configuration(sc, seed, last_step)};
  bool ok = replays_match(configurations[0]) && replays_match(configurations[1]);
  for (int r = 0; ok && r < repeat; ++r) {
    for (Configuration& c : configurations) ok = ok && time_replays(c, r == 0);
  }
  if (!ok) {
    std::cerr << "entourage-bench-meso: a replay did not compute what the live run did\n";
    return false;
  }
  print_table(configurations[0].figures, configurations[1].figures);
  print_vehicle_costs(configurations[0].figures, configurations[1].figures);
  print_live_and_checks(configurations[0].figures, configurations[1].figures);
  std::fflush(stdout);
  return true;
}

int run(int argc, char** argv) {
  std::string scenario_path;
  double duration_s = 600.0;
  std::uint64_t seed = 0;
  int repeat = 5;
  cli::Args args("entourage-bench-meso",
                 "CPU time per step of the generator, micro and meso cores, one process in lockstep with the "
                 "scenario's ego stand-in: the window all-micro against micro inside and meso outside, the saving, "
                 "and meso's cost per vehicle-step against micro's.");
  args.option("scenario", "FILE", "the scenario (default: scenarios/freeway.pbtxt and scenarios/rural.pbtxt)",
              &scenario_path);
  args.option("duration", "S", "simulated time per run (default 600)", &duration_s);
  args.option("seed", "N", "run seed (default: the scenario's)", &seed);
  args.option("repeat", "N", "timed replays of each core per run, the fastest counts (default 5)", &repeat);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  if (!std::isfinite(duration_s) || duration_s <= 0.0 || duration_s > 86400.0) {
    std::cerr << "entourage-bench-meso: --duration wants a simulated time in seconds, above 0 and at most 86400\n";
    return 2;
  }
  if (repeat < 1 || repeat > 1000) {
    std::cerr << "entourage-bench-meso: --repeat wants a number of replays from 1 to 1000\n";
    return 2;
  }
  std::vector<std::string> paths;
  if (scenario_path.empty()) {
    paths = {std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/freeway.pbtxt",
             std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/rural.pbtxt"};
  } else {
    paths = {scenario_path};
  }
  std::vector<ScenarioConfig> scenarios;
  for (const std::string& path : paths) {
    const auto loaded = scenario::load_file(path);
    if (!loaded.ok()) {
      for (const auto& p : loaded.problems) std::cerr << p.to_string() << "\n";
      return 2;
    }
    scenarios.push_back(loaded.config);
  }
  std::printf("meso against micro: CPU time of each core's step (thread CPU time), %.0f s simulated per run, "
              "the fastest of %d replays\n",
              duration_s, repeat);
  std::printf("host: %u logical CPUs, %s\n", std::thread::hardware_concurrency(), cpu_model().c_str());
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (!bench_scenario(paths[i], scenarios[i], seed, duration_s, repeat)) return 1;
  }
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) { return entourage::run(argc, argv); }
