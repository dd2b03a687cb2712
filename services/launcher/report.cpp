#include "launcher/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>

#include "core/units.hpp"
#include "recording/checks.hpp"
#include "recording/recording.hpp"
#include "recording/summary.hpp"
#include "recording/tables.hpp"

namespace entourage::launcher {

namespace {

std::string f1(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

std::string f2(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(i, v.size() - 1)];
}

std::vector<std::string> type_names(const ScenarioConfig& sc) {
  std::vector<std::string> names;
  for (const auto& t : sc.vehicle_types) names.push_back(t.name);
  return names;
}

void print_flow(const char* what, const recording::FlowMeasurement& f, std::ostream& out) {
  if (f.demand_veh_per_h <= 0.0 && f.crossings == 0) return;
  out << "  flow " << what << ": " << f1(f.measured_veh_per_h) << " veh/h measured in the window against a demand of "
      << f1(f.demand_veh_per_h) << " veh/h (" << (f.relative_error() >= 0 ? "+" : "") << f1(100.0 * f.relative_error())
      << " % ± " << f1(100.0 * f.relative_standard_error()) << " %; " << f.vehicles << " vehicles, " << f.crossings
      << " detector crossings in " << f1(f.observed_s / 3600.0) << " detector-hours)\n";
}

// Each service's CPU time per step while the run drove, and for the services that publish vehicle
// states, how many they wrote per step (their step reports' counts, else the recording's rows by
// owner): in a process, most of a step's CPU time goes to DDS (reading the world, writing each
// state), not to the core's model.
void print_service_cpu(const std::vector<ServiceCpu>& cpu, const std::map<std::string, std::uint64_t>& written,
                       const recording::Tables& tables, std::uint64_t steps, std::ostream& out) {
  if (cpu.empty() || steps == 0) return;
  std::map<std::string, std::uint64_t> states_by_service = written;
  if (states_by_service.empty()) {
    for (const auto& v : tables.vehicles) ++states_by_service[v.owner];
  }
  const auto per_step = [steps](double total) { return total / static_cast<double>(steps); };
  out << "  CPU per step while driving (each service's process, all its threads; vehicle states it wrote per step):";
  const char* separator = " ";
  for (const ServiceCpu& c : cpu) {
    out << separator << c.service << ' ' << f1(1e6 * per_step(c.cpu_s)) << " us";
    const auto states = states_by_service.find(c.service);
    if (states != states_by_service.end() && states->second > 0) {
      out << " (" << f1(per_step(static_cast<double>(states->second))) << ")";
    }
    separator = ", ";
  }
  out << "\n";
}

}  // namespace

bool print_report(const ReportInput& in, std::ostream& out) {
  std::string error;
  const auto rec = recording::read_recording(in.recording, &error);
  if (!rec) {
    out << "entourage: cannot read the recording: " << error << "\n";
    return false;
  }
  ReportInput with_counts = in;
  for (const msg::StepDone& d : rec->done) {
    with_counts.states_written[to_string(ServiceId::from_code(d.service()))] += d.vehicle_states();
  }
  return print_report(with_counts, recording::tables_from(*rec, type_names(in.scenario)), out);
}

bool print_report(const ReportInput& in, const recording::Tables& tables, std::ostream& out) {
  const auto s = recording::summarize(tables, in.scenario);
  out << "summary:\n";
  out << "  simulated " << f1(s.simulated_s) << " s (" << s.steps << " steps)";
  if (in.wall_s > 0.0) {
    out << " in " << f1(in.wall_s) << " s of wall time: " << f1(static_cast<double>(s.steps) / in.wall_s)
        << " steps/s";
  }
  out << "\n  vehicles generated " << s.generated << " (" << s.initial_fill << " by the initial fill), removed "
      << s.removed;
  if (s.taken_off > 0) out << " (" << s.taken_off << " of them taken off out of sight by the director)";
  out << ", handed between regions " << s.transfers << " times\n";
  out << "  mean speed:";
  for (const char* region : {"outer_rear", "inner", "outer_front"}) {
    auto it = s.mean_speed_mps.find(region);
    if (it != s.mean_speed_mps.end()) out << ' ' << region << ' ' << f1(mps_to_kph(it->second)) << " km/h;";
  }
  out << " ego " << f1(mps_to_kph(s.ego_mean_speed_mps)) << " km/h over " << f1(s.ego_distance_m / 1000.0) << " km\n";
  print_flow("forward", s.forward, out);
  print_flow("backward", s.backward, out);
  const auto& pe = s.past_ego;
  out << "  past the ego: " << pe.overtaking << " vehicles overtook it, it overtook " << pe.overtaken << ", it met "
      << pe.met << " oncoming; moving-observer flow " << f1(pe.forward_veh_per_h) << " veh/h forward, "
      << f1(pe.backward_veh_per_h) << " veh/h backward\n";
  const auto& pp = s.past_ego_predicted;
  const auto ratio = [](std::uint64_t n, double expected) {
    return expected > 0.0 ? f2(static_cast<double>(n) / expected) : std::string("-");
  };
  // A count's chance spread: Poisson's root of the prediction (at least: platoons pass together).
  const auto predicted = [](double expected) { return f1(expected) + " ± " + f1(std::sqrt(std::max(expected, 0.0))); };
  out << "  catch-ups against the moving-observer prediction: passive " << pe.overtaking_counted << " / "
      << predicted(pp.overtaking) << " (" << ratio(pe.overtaking_counted, pp.overtaking) << "), active "
      << pe.overtaken_counted << " / " << predicted(pp.overtaken) << " (" << ratio(pe.overtaken_counted, pp.overtaken)
      << "), oncoming met " << pe.met_counted << " / " << predicted(pp.met) << " (" << ratio(pe.met_counted, pp.met)
      << "); counted in " << f1(100.0 * pe.counted_share) << " % of the steps (the window on a stretch like the "
      << "reference road)\n";
  for (const auto& [name, f, lanes] :
       {std::tuple<const char*, const recording::FlowMeasurement&, int>{"forward", s.forward, in.scenario.road.lanes_forward},
        {"backward", s.backward, in.scenario.road.lanes_backward}}) {
    if (f.headways == 0) continue;
    out << "  platoons " << name << ": " << f1(100.0 * f.share_below()) << " % of " << f.headways
        << " headways in a lane below " << f1(recording::kPlatoonHeadway_s) << " s (mean platoon "
        << f2(recording::FlowMeasurement::platoon_size(f.share_below())) << " vehicles)";
    // The arrivals' headways are the direction's; on one lane they are the lane's too.
    if (lanes == 1) {
      out << "; the scenario's arrivals at the source: " << f1(100.0 * f.source_share_below) << " % ("
          << f2(recording::FlowMeasurement::platoon_size(f.source_share_below)) << ")";
    }
    out << "\n";
  }
  out << "  lane changes: " << s.manoeuvres.lane_changes;
  if (in.scenario.road.kind == RoadKind::kRural) {
    out << "; overtakings in the oncoming lane: " << s.manoeuvres.overtakings << " (by " << s.manoeuvres.overtakers
        << " vehicles)";
  }
  out << "\n";
  const auto& micro_in = s.transitions.into_micro;
  const auto& meso_in = s.transitions.into_meso;
  out << "  handovers meso to micro: " << micro_in.handoffs << "; largest deceleration in the first "
      << f1(recording::kIntoMicroWindow_s) << " s in micro: median " << f2(micro_in.median_decel_mps2) << ", 95th percentile "
      << f2(micro_in.p95_decel_mps2) << ", max " << f2(micro_in.max_decel_mps2) << " m/s2, " << micro_in.hard << " above "
      << f1(recording::kHardBorderDecel_mps2) << " m/s2\n";
  out << "  handovers micro to meso: " << meso_in.handoffs << "; lane kept " << meso_in.lane_kept << ", speed against micro's "
      << "last acceleration: mean " << f2(meso_in.mean_speed_jump_mps) << ", max " << f2(meso_in.max_speed_jump_mps)
      << " m/s\n";
  if (in.realtime && !in.latencies_ms.empty()) {
    out << "  ego state to world state: median " << f1(percentile(in.latencies_ms, 0.5)) << " ms, 99th percentile "
        << f1(percentile(in.latencies_ms, 0.99)) << " ms, max " << f1(percentile(in.latencies_ms, 1.0)) << " ms over "
        << in.latencies_ms.size() << " steps\n";
  }
  print_service_cpu(in.service_cpu, in.states_written, tables, s.steps, out);
  bool all_ok = true;
  out << "  invariants:\n";
  for (const auto& c : recording::check_invariants(tables, in.scenario.ego)) {
    out << "    " << (c.passed ? "ok     " : "FAILED ") << c.name << ": " << c.detail << "\n";
    all_ok = all_ok && c.passed;
  }
  if (tables.undecodable > 0) out << "  " << tables.undecodable << " recorded messages could not be decoded\n";
  out << "  recording: " << in.recording << " ("
      << tables.vehicles.size() + tables.ego.size() + tables.handoffs.size() << " samples)\n";
  if (!in.logs_dir.empty()) out << "  logs: " << in.logs_dir << "/\n";
  return all_ok;
}

}  // namespace entourage::launcher
