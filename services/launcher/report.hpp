#pragma once
// The summary printed at the end of a run (and by `entourage verify`), measured from the
// recording: what was generated and removed, handoffs, speeds per region, flow against demand,
// the design's invariants, and in real time the delay from ego state to world state.

#include <ostream>
#include <map>
#include <string>
#include <vector>

#include "recording/tables.hpp"
#include "scenario/config.hpp"

namespace entourage::launcher {

// A service's process and the CPU time it used while the run drove (from the first step on).
struct ServiceCpu {
  std::string service;  // as in the recording's owner column (micro, meso, meso-front, ...)
  double cpu_s = 0.0;
};

struct ReportInput {
  std::string recording;  // the recording's path (or the CSV directory it was exported to)
  std::string logs_dir;  // empty: not a run
  ScenarioConfig scenario;
  double wall_s = 0.0;  // 0: not a run
  bool realtime = false;
  std::vector<double> latencies_ms;
  std::vector<ServiceCpu> service_cpu;  // empty: not a run, or not measured
  // Vehicle states each service wrote over the run, by name as ServiceCpu::service (its step
  // reports' counts); empty: counted from the recording's rows by owner, which hold, for a service
  // whose states are carried forward, the rebuilt ones as well.
  std::map<std::string, std::uint64_t> states_written;
};

// Prints the report of a recording's rows (from the recording or its CSV export); false if an
// invariant is violated.
bool print_report(const ReportInput& in, const recording::Tables& tables, std::ostream& out);
// Reads in.recording and prints its report; false if it cannot be read or an invariant is violated.
bool print_report(const ReportInput& in, std::ostream& out);

}  // namespace entourage::launcher
