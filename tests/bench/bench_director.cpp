// entourage-bench-director: each shipped play run many times in lockstep (every core in one
// process, play_runs.hpp) with varied ego drivers and traffic seeds; prints the success rate, the
// errors at the handover, the start-time estimate's error, how hard actors drove while being moved
// into place against the autonomous vehicles of the same runs, where vehicles were created, and
// overlaps.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "failure_kinds.hpp"
#include "ordered_pool.hpp"
#include "paired_runs.hpp"
#include "play_runs.hpp"
#include "scenario/loader.hpp"

namespace entourage {
namespace {

// A handover this soon after the ego passed trigger point 2 is at it (the same step).
constexpr double kAtTrigger_s = 1e-6;
// A run whose ego the director held up longer than this is counted apart (a steady driver
// slowed by some 10 % over a preparation of about a minute).
constexpr double kLongHoldUp_s = 5.0;
// Traffic around the ego this much slower than without the director counts as slowed down.
constexpr double kSlowedTraffic = 0.8;

double mean(const std::vector<double>& x) {
  if (x.empty()) return 0.0;
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double percentile(std::vector<double> x, double q) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const auto i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(x.size())) - 1.0);
  return x[std::min(i, x.size() - 1)];
}

// One group's per-run largest acceleration, deceleration and jerk (runs where the group drove in
// the inner region while the play was prepared), printed as median / p95 / max over the runs.
struct ExtremesOverRuns {
  std::vector<double> accel, decel, jerk;
  void add(const bench::MotionExtremes& m) {
    if (m.vehicle_steps == 0) return;
    accel.push_back(m.max_accel_mps2);
    decel.push_back(m.max_decel_mps2);
    jerk.push_back(m.max_jerk_mps3);
  }
  void print(const char* group) const {
    std::printf("  %-11s accel %.2f / %.2f / %.2f m/s2   decel %.2f / %.2f / %.2f m/s2   jerk %.1f / %.1f / %.1f m/s3"
                "   (%zu runs)\n",
                group, percentile(accel, 0.5), percentile(accel, 0.95), percentile(accel, 1.0), percentile(decel, 0.5),
                percentile(decel, 0.95), percentile(decel, 1.0), percentile(jerk, 0.5), percentile(jerk, 0.95),
                percentile(jerk, 1.0), accel.size());
  }
};

void print_play(const std::string& name, const PlayConfig& play, const std::vector<bench::PlayRunResult>& runs,
                const std::vector<bench::EgoVariant>& variants) {
  std::vector<double> pos_t2, speed_t2;  // on passing trigger point 2
  std::vector<double> held_up;  // s, per run
  std::vector<double> pos, speed, est, a_beside, o_beside, slowed, waits, beyond, actor_held_up;
  double actor_held_up_s = 0.0, actor_held_up_by_commanded_s = 0.0;
  ExtremesOverRuns actors, cleared, autonomous;
  int taken_off = 0, taken_off_in_view = 0, taken_off_for_room = 0;
  int ok = 0, at_trigger = 0, created = 0, in_view = 0, overlaps_actor = 0, overlaps_other = 0, ego_contacts = 0,
      commanded_twice = 0;
  bench::SignalsCalledOff off_commanded, off_autonomous;
  bench::LaneChangesMade changes_commanded, changes_autonomous;
  bench::AboveTopSpeed above_commanded, above_autonomous;
  bench::RightPasses right, right_undirected;
  int runs_right = 0, runs_right_undirected = 0;  // runs in which the ego passed any on the right
  std::map<std::string, int> causes;
  std::map<std::string, int> missing_at_t2;  // runs in which each kind was missing at trigger point 2
  std::map<std::string, std::pair<int, int>> by_variant;  // ok, runs
  // By what the ego did with its lane between the trigger points (kept it or changed), and how
  // the play stood staged when it passed trigger point 2 (as written or mirrored): ok, runs.
  std::pair<int, int> by_lane[2][2] = {};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const bench::PlayRunResult& r = runs[i];
    auto& bv = by_variant[bench::to_string(variants[i])];
    ++bv.second;
    auto& bl = by_lane[r.ego_lane_changes > 0 ? 1 : 0][r.mirrored_at_trigger2 ? 1 : 0];
    ++bl.second;
    if (r.handed_over) {
      ++ok;
      ++bv.first;
      ++bl.first;
      waits.push_back(r.handover_wait_s);
      beyond.push_back(r.handover_beyond_m);
      if (r.handover_wait_s < kAtTrigger_s) ++at_trigger;
    } else {
      ++causes[r.failure.empty() ? std::string("never reached trigger point 2") : bench::cause_of(r.failure, play)];
    }
    for (const std::string& k : bench::kinds_of(r.missing_at_trigger2, play)) ++missing_at_t2[k];
    if (r.position_error_at_trigger2_m >= 0.0) {
      pos_t2.push_back(r.position_error_at_trigger2_m);
      speed_t2.push_back(std::abs(r.speed_error_at_trigger2_mps));
    }
    pos.push_back(std::abs(r.position_error_m));
    speed.push_back(std::abs(r.speed_error_mps));
    est.push_back(std::abs(r.estimate_error_s));
    held_up.push_back(r.held_up_s);
    actors.add(r.actors);
    cleared.add(r.cleared);
    autonomous.add(r.autonomous);
    a_beside.push_back(r.actor_beside_ego_s);
    actor_held_up.push_back(r.actor_held_up_s);
    actor_held_up_s += r.actor_held_up_s;
    actor_held_up_by_commanded_s += r.actor_held_up_by_commanded_s;
    if (r.traffic_slowed_to() > 0.0) slowed.push_back(r.traffic_slowed_to());
    o_beside.push_back(r.autonomous_beside_ego_s);
    off_commanded.add(r.called_off_commanded);
    right.add(r.passed_on_right);
    right_undirected.add(r.passed_on_right_undirected);
    runs_right += r.passed_on_right.total() > 0 ? 1 : 0;
    runs_right_undirected += r.passed_on_right_undirected.total() > 0 ? 1 : 0;
    off_autonomous.add(r.called_off_autonomous);
    changes_commanded.add(r.lane_changes_commanded);
    changes_autonomous.add(r.lane_changes_autonomous);
    above_commanded.add(r.above_top_commanded);
    above_autonomous.add(r.above_top_autonomous);
    created += r.created;
    in_view += r.created_in_view;
    taken_off += r.taken_off;
    taken_off_in_view += r.taken_off_in_view;
    taken_off_for_room += r.taken_off_for_room;
    overlaps_actor += r.overlaps_with_actor;
    overlaps_other += r.overlaps_other;
    ego_contacts += r.ego_contacts_with_actor;
    commanded_twice += r.commanded_twice_in_a_step;
  }
  const double n = static_cast<double>(runs.size());
  std::printf("\n== %s: %zu runs ==\n", name.c_str(), runs.size());
  const bench::RateInterval interval = bench::wilson_interval(ok, static_cast<int>(runs.size()));
  std::printf("success                        %d / %zu (%.1f %%, 95 %% interval %.0f-%.0f %%)", ok, runs.size(),
              100.0 * ok / n, 100.0 * interval.low, 100.0 * interval.high);
  for (const auto& [v, c] : by_variant) std::printf("   %s %d/%d", v.c_str(), c.first, c.second);
  std::printf("\n");
  for (const auto& [c, k] : causes) std::printf("  failed %3d x  %s\n", k, c.c_str());
  std::printf("missing on passing trigger point 2 (runs; one run may lack several):");
  if (missing_at_t2.empty()) std::printf(" nothing");
  for (const auto& [c, k] : missing_at_t2) std::printf("  %s %d", c.c_str(), k);
  std::printf("\n");
  std::printf("by the ego's lane, trigger point 1 to 2 (done / runs): kept it, the play as written %d/%d, mirrored %d/%d; "
              "changed it, as written at trigger point 2 %d/%d, mirrored %d/%d\n",
              by_lane[0][0].first, by_lane[0][0].second, by_lane[0][1].first, by_lane[0][1].second, by_lane[1][0].first,
              by_lane[1][0].second, by_lane[1][1].first, by_lane[1][1].second);
  std::printf("handed over at trigger point 2 %d / %zu (%.1f %%); after waiting beyond it: %d, waited mean %.1f  p95 %.1f  max %.1f s, "
              "the ego beyond it by mean %.0f  p95 %.0f  max %.0f m\n",
              at_trigger, runs.size(), 100.0 * at_trigger / n, ok - at_trigger, mean(waits), percentile(waits, 0.95),
              percentile(waits, 1.0), mean(beyond), percentile(beyond, 0.95), percentile(beyond, 1.0));
  std::printf("handover position error (m)    mean %.2f   p95 %.2f   (largest over the roles)\n", mean(pos), percentile(pos, 0.95));
  std::printf("handover speed error (km/h)    mean %.2f   p95 %.2f\n", 3.6 * mean(speed), 3.6 * percentile(speed, 0.95));
  std::printf("errors on passing trigger point 2 (%zu runs): position mean %.2f  p95 %.2f m, speed mean %.2f  "
              "p95 %.2f km/h\n",
              pos_t2.size(), mean(pos_t2), percentile(pos_t2, 0.95), 3.6 * mean(speed_t2), 3.6 * percentile(speed_t2, 0.95));
  std::printf("start-time estimate at trigger 1, |error| (s): mean %.2f   p95 %.2f\n", mean(est), percentile(est, 0.95));
  const auto long_holds = std::count_if(held_up.begin(), held_up.end(), [](double h) { return h > kLongHoldUp_s; });
  std::printf("the ego held up by the director, trigger point 1 to 2 against the same run without it (s): median %.1f  "
              "p95 %.1f  max %.1f; more than %.0f s in %td runs\n",
              percentile(held_up, 0.5), percentile(held_up, 0.95), percentile(held_up, 1.0), kLongHoldUp_s, long_holds);
  std::printf("while being moved into place (inner region), per run largest: median / p95 / max\n");
  actors.print("actors");
  cleared.print("cleared");
  autonomous.print("autonomous");
  std::printf("traffic of the ego's direction in the inner region, trigger point 1 to 2, mean speed with the director\n"
              "  of that without, per run: median %.2f  p5 %.2f  min %.2f; below 0.8 in %td runs\n",
              percentile(slowed, 0.5), percentile(slowed, 0.05),
              slowed.empty() ? 0.0 : *std::min_element(slowed.begin(), slowed.end()),
              std::count_if(slowed.begin(), slowed.end(), [](double x) { return x < kSlowedTraffic; }));
  std::printf("longest beside the ego (next lane, within %.0f m) while preparing, per run: median / p95 / max\n"
              "  actors      %.1f / %.1f / %.1f s\n  autonomous  %.1f / %.1f / %.1f s\n",
              bench::kBesideEgo_m, percentile(a_beside, 0.5), percentile(a_beside, 0.95), percentile(a_beside, 1.0),
              percentile(o_beside, 0.5), percentile(o_beside, 0.95), percentile(o_beside, 1.0));
  std::printf("actors held up in their lane while preparing (over %.0f m/s below the desired speed given, within %.0f s\n"
              "  of a leader), per run: median / p95 / max %.1f / %.1f / %.1f s; behind one under a command %.0f %% of it\n",
              bench::kHeldUpBelow_mps, bench::kHeldUpWithin_s, percentile(actor_held_up, 0.5),
              percentile(actor_held_up, 0.95), percentile(actor_held_up, 1.0),
              actor_held_up_s > 0.0 ? 100.0 * actor_held_up_by_commanded_s / actor_held_up_s : 0.0);
  std::printf("vehicles the ego passed on the right, trigger point 1 to 2 (it in a lane right of theirs)\n"
              "  with the director     %d (%d under its command) in %d runs\n"
              "  without the director  %d in %d runs\n",
              right.total(), right.commanded, runs_right, right_undirected.total(), runs_right_undirected);
  std::printf("faster than any driver of their type wishes (inner region, while preparing)\n"
              "  commanded   %.1f vehicle-s in %d runs, by at most %.1f km/h\n"
              "  autonomous  %.1f vehicle-s in %d runs, by at most %.1f km/h\n",
              above_commanded.vehicle_s, above_commanded.runs, 3.6 * above_commanded.max_excess_mps,
              above_autonomous.vehicle_s, above_autonomous.runs, 3.6 * above_autonomous.max_excess_mps);
  std::printf("lane changes called off (indicator on, then off in the same lane; inner region, while preparing)\n"
              "  commanded   %d in %.1f vehicle-hours (%.1f per vehicle-hour)\n"
              "  autonomous  %d in %.1f vehicle-hours (%.1f per vehicle-hour)\n",
              off_commanded.count, off_commanded.vehicle_s / 3600.0, off_commanded.per_vehicle_hour(),
              off_autonomous.count, off_autonomous.vehicle_s / 3600.0, off_autonomous.per_vehicle_hour());
  std::printf("lane changes made (inner region, while preparing); most by one vehicle in a run, runs in which one made %d+\n"
              "  commanded   %d in %.1f vehicle-hours (%.1f per vehicle-hour); most %d, %d runs\n"
              "  autonomous  %d in %.1f vehicle-hours (%.1f per vehicle-hour); most %d, %d runs\n",
              bench::kManyLaneChanges, changes_commanded.count, changes_commanded.vehicle_s / 3600.0,
              changes_commanded.per_vehicle_hour(), changes_commanded.most_by_one, changes_commanded.runs_with_many,
              changes_autonomous.count, changes_autonomous.vehicle_s / 3600.0, changes_autonomous.per_vehicle_hour(),
              changes_autonomous.most_by_one, changes_autonomous.runs_with_many);
  std::printf("indicator on, per signal that went off in view: median / p95 / max\n"
              "  commanded   %.1f / %.1f / %.1f s   (%zu signals)\n  autonomous  %.1f / %.1f / %.1f s   (%zu signals)\n",
              percentile(off_commanded.signal_s, 0.5), percentile(off_commanded.signal_s, 0.95),
              percentile(off_commanded.signal_s, 1.0), off_commanded.signal_s.size(),
              percentile(off_autonomous.signal_s, 0.5), percentile(off_autonomous.signal_s, 0.95),
              percentile(off_autonomous.signal_s, 1.0), off_autonomous.signal_s.size());
  std::printf("vehicles created               %d   of which inside the view: %d\n", created, in_view);
  std::printf("vehicles taken off the road    %d   of which inside the view: %d   (oncoming, for a gap; of the ego's "
              "direction, to make room for a creation: %d)\n",
              taken_off, taken_off_in_view, taken_off_for_room);
  std::printf("overlapping pairs              with an actor %d   autonomous only %d   ego touching an actor %d\n",
              overlaps_actor, overlaps_other, ego_contacts);
  std::printf("a vehicle commanded twice in one step (one phase undoing another's command): %d\n", commanded_twice);
}

void print_paired(const std::string& path, const std::map<std::uint64_t, bool>& before,
                  const std::vector<bench::PlayRunResult>& results, std::uint64_t first_seed) {
  std::map<std::uint64_t, bool> now;
  for (std::size_t i = 0; i < results.size(); ++i) {
    now[first_seed + i] = results[i].final_phase == director::PlayPhase::kDone;
  }
  const bench::PairedRuns p = bench::pair_runs(before, now);
  std::printf("paired with %s: gained %d, lost %d (both done %d, both failed %d, not in it %d); "
              "McNemar's p = %.3f\n",
              path.c_str(), p.gained, p.lost, p.both_done, p.both_failed, p.unpaired, bench::flips_p_value(p.gained, p.lost));
}

// One run of a play: its result, the ego's driver, and its trace (--trace, --trace-traffic) as
// text, so that runs on several threads print it in run order.
struct RunOutcome {
  std::uint64_t seed = 0;
  bench::PlayRunResult result;
  bench::EgoVariant variant{};
  std::string trace;
};

// `live`: where the trace goes as the run makes it (one thread); null: into the outcome, printed
// when its turn comes (several threads).
RunOutcome run_once(const ScenarioConfig& config, int index, std::uint64_t first_seed, bool plain, bool trace,
                    bool trace_traffic, std::FILE* live) {
  RunOutcome o;
  o.seed = first_seed + static_cast<std::uint64_t>(index);
  const std::uint64_t s = o.seed;
  const ScenarioConfig sc = plain ? config : bench::vary_ego(config, index, s, &o.variant);
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* out = nullptr;  // the trace's stream, when traced
  if (trace || trace_traffic) {
    out = live != nullptr ? live : open_memstream(&text, &size);
    if (out == nullptr) throw std::runtime_error("cannot buffer the trace of run " + std::to_string(index));
  }
  o.result = bench::run_play(sc, s, trace ? out : nullptr, trace_traffic ? out : nullptr);
  if (out != nullptr && out != live) {
    std::fclose(out);
    o.trace.assign(text, size);
    std::free(text);
  }
  const bench::TriggerTimes undirected = bench::trigger_times_undirected(sc, s);
  bench::PlayRunResult& r = o.result;
  if (r.trigger2_time_s >= 0.0 && undirected.trigger2_s >= 0.0) {
    r.held_up_s = (r.trigger2_time_s - r.trigger1_time_s) - (undirected.trigger2_s - undirected.trigger1_s);
  }
  r.traffic_speed_undirected_mps = undirected.traffic_speed_mps;
  r.passed_on_right_undirected = undirected.passed_on_right;
  return o;
}

void print_run_line(int index, const RunOutcome& o) {
  const bench::PlayRunResult& r = o.result;
  std::printf("run %d seed %llu %-12s %-11s pos %6.1f m speed %5.1f km/h estimate %+6.1f s waited %4.1f s created %d "
              "overlaps %d/%d held up %4.1f s beside %4.1f s traffic %4.2f right %d/%d actors' decel %3.1f m/s2 "
              "actors held up %4.1f s ego lane changes %d%s  %s\n",
              index, static_cast<unsigned long long>(o.seed), bench::to_string(o.variant),
              director::to_string(r.final_phase), r.position_error_m, 3.6 * r.speed_error_mps, r.estimate_error_s,
              r.handover_wait_s, r.created, r.overlaps_with_actor, r.overlaps_other, r.held_up_s, r.actor_beside_ego_s,
              r.traffic_slowed_to(), r.passed_on_right.total(), r.passed_on_right_undirected.total(),
              r.actors.max_decel_mps2, r.actor_held_up_s, r.ego_lane_changes, r.mirrored_at_trigger2 ? " mirrored" : "",
              r.failure.c_str());
}

int run(int argc, char** argv) {
  std::string scenario_path;
  int runs = 50;
  int first = 0;
  std::uint64_t seed = 1;
  bool verbose = false;
  bool plain = false;
  bool trace = false;
  bool trace_traffic = false;
  int jobs = 0;
  cli::Args args("entourage-bench-director",
                 "Runs each shipped play many times in lockstep (every core in one process) with varied ego drivers "
                 "and traffic seeds, and prints success, handover errors, the actors' driving against the "
                 "autonomous vehicles', creations and overlaps.");
  args.option("scenario", "FILE", "one scenario with a play (default: the four shipped play scenarios)", &scenario_path);
  args.option("runs", "N", "runs per play (default 50)", &runs);
  args.option("seed", "N", "first traffic seed; run i uses seed + i (default 1)", &seed);
  args.option("first", "I", "index of the first run (default 0): runs I .. I+N-1, to repeat one run of a longer bench", &first);
  args.option("jobs", "N", "runs on N threads at once (default 0: one per logical CPU); the output is the same", &jobs);
  args.flag("verbose", "one line per run as well", &verbose);
  args.flag("trace", "every play report of every run as well (to stderr)", &trace);
  args.flag("trace-traffic", "the vehicles around the ego every 2 s of every play as well (to stderr)", &trace_traffic);
  args.flag("plain", "the scenario's own ego driver in every run (only the traffic seed varies)", &plain);
  std::string play_name;
  args.option("play", "NAME",
              "in a scenario with several plays, the one to measure (default: its first); the others are "
              "prepared and run as well",
              &play_name);
  std::string paired_path;
  args.option("paired", "FILE",
              "a previous --verbose output of the same scenario: the runs this version gained and lost against it, "
              "paired by seed, and McNemar's p-value",
              &paired_path);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  if (runs < 1 || runs > 100000) {
    std::cerr << "entourage-bench-director: --runs wants a number from 1 to 100000\n";
    return 2;
  }
  if (jobs < 0 || jobs > 1024) {
    std::cerr << "entourage-bench-director: --jobs wants a number from 0 (one per logical CPU) to 1024\n";
    return 2;
  }
  if (first < 0 || first > 100000) {
    std::cerr << "entourage-bench-director: --first wants a number from 0 to 100000\n";
    return 2;
  }
  std::map<std::uint64_t, bool> paired_before;
  if (!paired_path.empty()) {
    if (scenario_path.empty()) {
      std::cerr << "entourage-bench-director: --paired wants one --scenario (the runs are paired by seed)\n";
      return 2;
    }
    std::ifstream f(paired_path);
    if (!f) {
      std::cerr << "entourage-bench-director: cannot read " << paired_path << "\n";
      return 2;
    }
    std::stringstream text;
    text << f.rdbuf();
    paired_before = bench::outcomes_by_seed(text.str());
    if (paired_before.empty()) {
      std::cerr << "entourage-bench-director: " << paired_path << " has no run lines (want a --verbose output)\n";
      return 2;
    }
  }
  std::vector<std::string> paths;
  if (scenario_path.empty()) {
    for (const char* f : {"freeway_lead_brakes", "freeway_cut_in", "freeway_stopped_vehicle", "rural_slow_truck"}) {
      paths.push_back(std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/" + f + ".pbtxt");
    }
  } else {
    paths = {scenario_path};
  }
  for (const std::string& path : paths) {
    auto loaded = scenario::load_file(path);
    if (!loaded.ok()) {
      for (const auto& p : loaded.problems) std::cerr << p.to_string() << "\n";
      return 2;
    }
    if (loaded.config.plays.empty()) {
      std::cerr << "entourage-bench-director: " << path << " has no play\n";
      return 2;
    }
    if (!play_name.empty() && !bench::measure_play(loaded.config, play_name)) {
      std::cerr << "entourage-bench-director: " << path << " has no play named \"" << play_name << "\" (it has";
      for (const PlayConfig& p : loaded.config.plays) std::cerr << " \"" << p.name << "\"";
      std::cerr << ")\n";
      return 2;
    }
    const std::size_t n = static_cast<std::size_t>(runs);
    std::vector<RunOutcome> outcomes(n);
    std::vector<bench::PlayRunResult> results;
    std::vector<bench::EgoVariant> variants;
    const int threads = bench::pool_threads(jobs, n);
    std::FILE* live = threads == 1 ? stderr : nullptr;  // one thread: the trace as it comes
    bench::run_in_order(
        n, threads,
        [&](std::size_t k) {
          outcomes[k] = run_once(loaded.config, first + static_cast<int>(k), seed, plain, trace, trace_traffic, live);
        },
        [&](std::size_t k) {
          RunOutcome& o = outcomes[k];
          std::fwrite(o.trace.data(), 1, o.trace.size(), stderr);  // empty unless traced
          if (verbose) print_run_line(first + static_cast<int>(k), o);
          std::fflush(stdout);
          results.push_back(std::move(o.result));
          variants.push_back(o.variant);
          o = RunOutcome{};
        });
    print_play(loaded.config.plays.front().name + " (" + loaded.config.name + ")", loaded.config.plays.front(), results,
               variants);
    if (!paired_path.empty()) print_paired(paired_path, paired_before, results, seed + static_cast<std::uint64_t>(first));
  }
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) {
  try {
    return entourage::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "entourage-bench-director: " << e.what() << "\n";
    return 1;
  }
}
