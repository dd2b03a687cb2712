// entourage run: every service as its own process over DDS, progress while it runs, a summary.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "cli/args.hpp"
#include "dds/domain_ports.hpp"
#include "dds/runtime.hpp"
#include "launcher/commands.hpp"
#include "launcher/monitor.hpp"
#include "launcher/process.hpp"
#include "launcher/report.hpp"
#include "scenario/loader.hpp"

namespace entourage::launcher {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr auto kTick = std::chrono::milliseconds(50);
constexpr double kStopTimeout_s = 10.0;        // SIGTERM, then SIGKILL after this
constexpr double kLockstepStall_s = 60.0;      // no step for this long: the run has hung
constexpr Step kRealtimeLateSteps = 10;        // a service this far behind the ego is reported
constexpr double kProgressPeriodTty_s = 0.5;
constexpr double kProgressPeriodLog_s = 10.0;
constexpr std::size_t kLogTailLines = 15;

struct RunOptions {
  std::string scenario;
  bool lockstep = false;
  bool realtime = false;
  std::uint64_t seed = 0;
  double duration_s = -1.0;
  std::string record;
  int domain = 0;
  bool external_ego = false;
  std::string meso = "single";
  std::string meso_states = "auto";
  bool quiet = false;
  double discovery_timeout_s = 60.0;
  std::string bin_dir;
};

std::string executable_dir() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("build/bin") : self.parent_path().string();
}

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&now));
  return buf;
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : sep) + s;
  return out;
}

class Run {
 public:
  Run(RunOptions opt, scenario::Loaded sc) : opt_(std::move(opt)), sc_(std::move(sc)) {}
  int execute();

 private:
  void plan();
  bool spawn();
  bool wait_ready();
  enum class Outcome { kFinished, kInterrupted, kFailed };
  Outcome drive();
  // Each service's CPU time from the first step to now (services whose figure cannot be read, e.g.
  // one that has ended, are left out).
  std::vector<ServiceCpu> cpu_while_driving() const;
  bool stop_all();
  bool child_failed(std::string* who);
  void print_progress(const Snapshot& s, bool final_line);
  std::optional<Step> finished_step(const Snapshot& s) const;

  RunOptions opt_;
  scenario::Loaded sc_;
  std::uint64_t seed_ = 0;
  Step steps_ = 0;
  std::vector<std::string> services_;  // names of the services this run starts
  std::vector<std::string> peers_;     // every service taking part (external ego excluded)
  std::string logs_dir_;
  std::vector<std::unique_ptr<Child>> children_;
  // The monitor before the node: members go in reverse order, and the node's readers call into
  // the monitor until the node is gone (a step report arriving from an external simulator while
  // the node was deleted ran the freed monitor's handler: the launcher hung for good).
  std::unique_ptr<Monitor> monitor_;
  std::unique_ptr<dds::Node> node_;
  Clock::time_point started_;
  Clock::time_point last_progress_;
  Step last_progress_step_ = 0;
  double wall_s_ = 0.0;
  std::vector<std::optional<double>> cpu_at_start_s_;  // each child's CPU time when the run began to drive
  bool tty_ = false;
};

void Run::plan() {
  const ScenarioConfig& c = sc_.config;
  seed_ = opt_.seed != 0 ? opt_.seed : c.seed;
  const double duration = opt_.duration_s >= 0.0 ? opt_.duration_s : c.duration_s;
  steps_ = static_cast<Step>(std::llround(duration / c.step_s));
  if (opt_.record.empty()) opt_.record = "runs/" + c.name + "-" + timestamp() + ".mcap";
  fs::path rec(opt_.record);
  if (rec.has_parent_path()) fs::create_directories(rec.parent_path());
  logs_dir_ = (rec.parent_path() / (rec.stem().string() + ".logs")).string();
  fs::create_directories(logs_dir_);
  if (!opt_.external_ego) services_.push_back("ego");
  services_.insert(services_.end(), {"generator", "micro"});
  if (opt_.meso == "split") {
    services_.insert(services_.end(), {"meso-front", "meso-rear"});
  } else {
    services_.push_back("meso");
  }
  services_.insert(services_.end(), {"director", "recorder"});
  peers_ = services_;
}

bool Run::spawn() {
  const std::string mode = opt_.realtime ? "realtime" : "lockstep";
  for (const auto& name : services_) {
    const std::string exe = name.rfind("meso", 0) == 0 ? "entourage-meso" : "entourage-" + name;
    std::vector<std::string> argv{opt_.bin_dir + "/" + exe, "--scenario", opt_.scenario, "--domain",
                                  std::to_string(opt_.domain), "--seed", std::to_string(seed_), "--mode", mode,
                                  "--peers", join(peers_, ","), "--qos", dds::default_qos_file(),
                                  "--discovery-timeout", std::to_string(opt_.discovery_timeout_s)};
    if (name == "ego") argv.insert(argv.end(), {"--duration", std::to_string(opt_.duration_s >= 0.0 ? opt_.duration_s : sc_.config.duration_s)});
    if (name == "recorder") argv.insert(argv.end(), {"--out", opt_.record});
    if (name == "meso-front") argv.insert(argv.end(), {"--regions", "front"});
    if (name == "meso-rear") argv.insert(argv.end(), {"--regions", "rear"});
    if (name.rfind("meso", 0) == 0 && opt_.meso_states == "carried") argv.emplace_back("--carried-states");
    auto child = std::make_unique<Child>(name, argv, logs_dir_ + "/" + name + ".log");
    std::string error;
    if (!child->start(&error)) {
      std::cerr << "entourage: cannot start " << name << ": " << error << "\n";
      return false;
    }
    children_.push_back(std::move(child));
  }
  return true;
}

bool Run::child_failed(std::string* who) {
  for (auto& c : children_) {
    if (!c->running() && c->exit_code()) {
      *who = c->name() + " exited with code " + std::to_string(*c->exit_code()) + "; the end of " + c->log_path() +
             ":\n" + c->log_tail(kLogTailLines);
      return true;
    }
  }
  return false;
}

bool Run::wait_ready() {
  const auto t0 = Clock::now();
  while (!dds::shutdown_requested()) {
    std::string failure;
    if (child_failed(&failure)) {
      std::cerr << "entourage: " << failure;
      return false;
    }
    const Snapshot s = monitor_->snapshot();
    std::vector<std::string> missing;
    for (const auto& name : services_) {
      const auto id = service_from_name(name);
      auto it = s.statuses.find(id->code());
      const bool ready = it != s.statuses.end() &&
                         it->second.state() >= static_cast<std::uint8_t>(dds::ServiceState::kReady) &&
                         it->second.state() <= static_cast<std::uint8_t>(dds::ServiceState::kRunning);
      if (!ready) missing.push_back(name + (it == s.statuses.end() ? " (not heard from)" : " (" + it->second.detail().to_string() + ")"));
    }
    if (opt_.external_ego && !s.ego_step) missing.push_back("ego (external simulator: no ego state yet)");
    if (missing.empty()) return true;
    if (std::chrono::duration<double>(Clock::now() - t0).count() > opt_.discovery_timeout_s + 5.0) {
      std::cerr << "entourage: services not ready after " << opt_.discovery_timeout_s << " s:\n";
      for (const auto& m : missing) std::cerr << "  " << m << "\n";
      return false;
    }
    std::this_thread::sleep_for(kTick);
  }
  return false;
}

std::optional<Step> Run::finished_step(const Snapshot& s) const {
  if (!opt_.external_ego) {
    auto it = s.statuses.find(ServiceId{Role::kEgo, 0}.code());
    if (it != s.statuses.end() && it->second.state() == static_cast<std::uint8_t>(dds::ServiceState::kFinished)) {
      return it->second.last_step();
    }
    return std::nullopt;
  }
  auto it = s.last_step_done.find(ServiceId{Role::kRecorder, 0}.code());
  if (it != s.last_step_done.end() && it->second >= steps_) return it->second;
  return std::nullopt;
}

void Run::print_progress(const Snapshot& s, bool final_line) {
  if (opt_.quiet) return;
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - last_progress_).count();
  if (!final_line && since < (tty_ ? kProgressPeriodTty_s : kProgressPeriodLog_s)) return;
  const Step step = s.ego_step.value_or(0);
  const double rate = since > 0.0 ? static_cast<double>(step - std::min(step, last_progress_step_)) / since : 0.0;
  std::uint32_t micro = 0;
  std::uint32_t meso = 0;
  for (const auto& [code, n] : s.owned) {
    const Role r = ServiceId::from_code(code).role;
    if (r == Role::kMicro) micro += n;
    if (r == Role::kMeso) meso += n;
  }
  char line[200];
  std::snprintf(line, sizeof line, "  t %7.1f s  step %6llu/%llu  %6.0f steps/s  ego %5.1f km/h  vehicles: inner %3u, outer %3u",
                static_cast<double>(step) * sc_.config.step_s, static_cast<unsigned long long>(step),
                static_cast<unsigned long long>(steps_), rate, s.ego_speed_mps * 3.6, micro, meso);
  std::cout << (tty_ ? "\r" : "") << line << (tty_ && !final_line ? "" : "\n") << std::flush;
  last_progress_ = now;
  last_progress_step_ = step;
}

Run::Outcome Run::drive() {
  Step last_seen = 0;
  auto last_advance = Clock::now();
  auto last_late_report = Clock::time_point{};
  while (true) {
    if (dds::shutdown_requested()) return Outcome::kInterrupted;
    std::string failure;
    if (child_failed(&failure)) {
      std::cerr << (tty_ ? "\n" : "") << "entourage: " << failure;
      return Outcome::kFailed;
    }
    const Snapshot s = monitor_->snapshot();
    if (auto done = finished_step(s)) {
      print_progress(s, true);
      return Outcome::kFinished;
    }
    const Step step = s.ego_step.value_or(0);
    if (step != last_seen) {
      last_seen = step;
      last_advance = Clock::now();
    } else if (!opt_.realtime && std::chrono::duration<double>(Clock::now() - last_advance).count() > kLockstepStall_s) {
      std::cerr << "\nentourage: no step for " << kLockstepStall_s << " s; services' last steps:";
      for (const auto& [code, k] : s.last_step_done) std::cerr << ' ' << to_string(ServiceId::from_code(code)) << '=' << k;
      std::cerr << "\n";
      return Outcome::kFailed;
    }
    if (opt_.realtime && Clock::now() - last_late_report > std::chrono::seconds(5)) {
      for (const auto& [code, k] : s.last_step_done) {
        if (step > k + kRealtimeLateSteps) {
          std::cerr << (tty_ ? "\n" : "") << "entourage: " << to_string(ServiceId::from_code(code)) << " is "
                    << step - k << " steps behind the ego\n";
          last_late_report = Clock::now();
        }
      }
    }
    print_progress(s, false);
    std::this_thread::sleep_for(kTick);
  }
}

std::vector<ServiceCpu> Run::cpu_while_driving() const {
  std::vector<ServiceCpu> out;
  for (std::size_t i = 0; i < children_.size() && i < cpu_at_start_s_.size(); ++i) {
    const std::optional<double> now = children_[i]->cpu_s();
    if (now && cpu_at_start_s_[i]) out.push_back({children_[i]->name(), *now - *cpu_at_start_s_[i]});
  }
  return out;
}

// One service at a time, in the order they were started (the ego, the source of the steps, first;
// the recorder last), so that only one participant leaves the domain at a time.
bool Run::stop_all() {
  bool clean = true;
  for (auto& c : children_) {
    c->signal(SIGTERM);
    if (!c->wait(kStopTimeout_s)) {
      std::cerr << "entourage: " << c->name() << " did not stop within " << kStopTimeout_s << " s; killing it\n";
      c->signal(SIGKILL);
      c->wait(kStopTimeout_s);
    }
    if (aborted_in_fastdds_lease_race(*c, kLogTailLines)) {
      std::cerr << "entourage: warning: " << c->name()
                << " aborted inside Fast DDS while leaving the DDS domain (a known race of Fast DDS 2.9.1, "
                   "PDP::check_remote_participant_liveliness; see "
                << c->log_path() << "); its work was done\n";
      continue;
    }
    if (c->killed_by_us() || c->exit_code().value_or(1) != 0) clean = false;
  }
  const bool any_killed = std::any_of(children_.begin(), children_.end(),
                                      [](const auto& c) { return c->exit_code().value_or(0) >= 128; });
  if (any_killed && std::system("fastdds shm clean >/dev/null 2>&1") != 0) {
    std::cerr << "entourage: `fastdds shm clean` failed; shared-memory files may remain in /dev/shm\n";
  }
  return clean;
}

int Run::execute() {
  tty_ = ::isatty(STDOUT_FILENO) != 0;
  plan();
  dds::install_shutdown_handlers();
  node_ = std::make_unique<dds::Node>(opt_.domain, dds::default_qos_file(), "launcher");
  std::vector<ServiceId> producers;
  for (const auto& name : services_) {
    const auto id = service_from_name(name);
    if (id->role == Role::kMicro || id->role == Role::kMeso) producers.push_back(*id);
  }
  monitor_ = std::make_unique<Monitor>(*node_, producers);

  std::cout << "entourage: " << sc_.config.name << " (" << opt_.scenario << "), seed " << seed_ << ", "
            << (opt_.realtime ? "real time" : "lockstep") << ", " << steps_ << " steps of " << sc_.config.step_s
            << " s, DDS domain " << opt_.domain << "\n  services: " << join(services_, ", ")
            << (opt_.meso_states == "carried" ? " (meso writes only the states its readers cannot carry forward)" : "")
            << "\n  logs: " << logs_dir_ << "/\n";
  if (!spawn()) {
    stop_all();
    return 1;
  }
  if (!wait_ready()) {
    stop_all();
    return 1;
  }
  started_ = last_progress_ = Clock::now();
  for (const auto& c : children_) cpu_at_start_s_.push_back(c->cpu_s());
  const Outcome outcome = drive();
  wall_s_ = std::chrono::duration<double>(Clock::now() - started_).count();
  const std::vector<ServiceCpu> cpu = cpu_while_driving();
  if (outcome == Outcome::kInterrupted) std::cout << (tty_ ? "\n" : "") << "entourage: interrupted; stopping the services\n";
  ReportInput in{opt_.record, logs_dir_, sc_.config, wall_s_, opt_.realtime, monitor_->latencies_ms(), cpu, {}};
  // The launcher leaves the domain before the services do: it then never handles a service's
  // leaving (where Fast DDS 2.9.1's lease race lies, see stop_all).
  node_.reset();  // first: its readers' handlers are the monitor's
  monitor_.reset();
  const bool clean = stop_all();
  const bool report_ok = print_report(in, std::cout);
  if (outcome == Outcome::kFailed || !clean) {
    std::cerr << "entourage: the run failed; see the logs in " << logs_dir_ << "/\n";
    return 1;
  }
  if (outcome == Outcome::kInterrupted) return 130;
  return report_ok ? 0 : 1;
}

}  // namespace

int run_command(int argc, char** argv) {
  RunOptions opt;
  opt.bin_dir = executable_dir();
  cli::Args args("entourage run", "Runs a scenario with every service as its own process over DDS.");
  args.positional("SCENARIO", "scenario file (e.g. scenarios/freeway.pbtxt)", &opt.scenario);
  args.flag("lockstep", "a step advances when every service has finished the previous one (default)", &opt.lockstep);
  args.flag("realtime", "steps are paced by the wall clock at the scenario's step_s", &opt.realtime);
  args.option("seed", "N", "random seed (default: the scenario's)", &opt.seed);
  args.option("duration", "SECONDS", "simulated time (default: the scenario's duration_s)", &opt.duration_s);
  args.option("record", "FILE", "recording to write (default runs/<scenario>-<time>.mcap)", &opt.record);
  args.option("domain", "ID", "DDS domain id, 0-232 (default 0)", &opt.domain);
  args.flag("external-ego", "do not start the ego stand-in: a simulator publishes the ego state", &opt.external_ego);
  args.option("meso", "single|split", "one meso process for both outer regions, or one per region (default single)",
              &opt.meso);
  args.option("meso-states", "auto|every|carried",
              "meso publishes every vehicle state at every step, or only those a reader cannot carry forward from "
              "the last it got, the readers carrying the others forward (lockstep only); auto, the default: carried "
              "in lockstep with the ego stand-in, every in real time or with an external ego (a simulator reading "
              "the vehicle states itself)",
              &opt.meso_states);
  args.option("discovery-timeout", "SECONDS", "give up waiting for the services after this (default 60)",
              &opt.discovery_timeout_s);
  args.option("bin-dir", "DIR", "where the service executables are (default: beside entourage)", &opt.bin_dir);
  args.flag("quiet", "no progress lines", &opt.quiet);
  if (const auto rc = args.parse_or_exit(argc, argv, 2)) return *rc;
  if (opt.lockstep && opt.realtime) {
    std::cerr << "entourage run: --lockstep and --realtime exclude each other\n";
    return 2;
  }
  if (opt.meso != "single" && opt.meso != "split") {
    std::cerr << "entourage run: --meso must be single or split\n";
    return 2;
  }
  if (opt.meso_states != "auto" && opt.meso_states != "every" && opt.meso_states != "carried") {
    std::cerr << "entourage run: --meso-states must be auto, every or carried\n";
    return 2;
  }
  if (opt.meso_states == "carried" && opt.realtime) {
    std::cerr << "entourage run: --meso-states carried needs lockstep: in real time a reader may miss a step of meso "
                 "and could not carry its states forward\n";
    return 2;
  }
  if (opt.meso_states == "auto") opt.meso_states = opt.realtime || opt.external_ego ? "every" : "carried";
  if (opt.domain < 0 || opt.domain > 232) {
    std::cerr << "entourage run: --domain must be in 0-232\n";
    return 2;
  }
  // A domain whose ports lie in the ephemeral range works until a random port takes one
  // (dds/domain_ports.hpp): said at the start, not failed, since the range is the host's to set.
  if (const std::string w = dds::ephemeral_clash_here(opt.domain); !w.empty()) {
    std::cerr << "entourage run: warning: " << w << "\n";
  }
  scenario::Loaded sc = scenario::load_file(opt.scenario);
  if (!sc.ok()) {
    for (const auto& p : sc.problems) std::cerr << p.to_string() << "\n";
    std::cerr << "entourage run: " << opt.scenario << " has " << sc.problems.size()
              << " problem(s); no service was started\n";
    return 2;
  }
  return Run(std::move(opt), std::move(sc)).execute();
}

}  // namespace entourage::launcher
