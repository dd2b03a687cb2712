#include "dds/runtime.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <thread>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "dds/domain_ports.hpp"

#ifndef ENTOURAGE_DEFAULT_QOS_FILE
#define ENTOURAGE_DEFAULT_QOS_FILE "entourage_qos.xml"
#endif

namespace entourage::dds {

namespace {
// Set by SIGINT/SIGTERM; a signal handler may only touch a lock-free flag of static storage.
volatile std::sig_atomic_t g_shutdown = 0;
extern "C" void on_shutdown_signal(int) { g_shutdown = 1; }

constexpr auto kWaitSlice = std::chrono::milliseconds(100);
constexpr auto kStatusPeriod = std::chrono::seconds(1);
constexpr auto kDiscoveryPoll = std::chrono::milliseconds(50);
constexpr int kMaxDomainId = 232;  // RTPS port mapping limit
// A lockstep wait longer than this is logged with what is missing (the run continues to wait).
constexpr auto kStallReport = std::chrono::seconds(10);

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string lacking_matches(const Node& node, ServiceId self, const std::vector<ServiceId>& peers) {
  std::ostringstream os;
  for (const auto& t : all_topics()) {
    if (reads(self.role, t.topic)) {
      const int want = expected_writers(t.topic, peers, self);
      const int have = node.matched_writers(t.topic);
      if (have < want) os << ' ' << t.name << " writers " << have << '/' << want;
    }
    if (writes(self.role, t.topic)) {
      const int want = expected_readers(t.topic, peers, self);
      const int have = node.matched_readers(t.topic);
      if (have < want) os << ' ' << t.name << " readers " << have << '/' << want;
    }
  }
  return os.str();
}
}  // namespace

std::string default_qos_file() {
  const char* env = std::getenv("ENTOURAGE_QOS");
  return env != nullptr && *env != '\0' ? env : ENTOURAGE_DEFAULT_QOS_FILE;
}

std::optional<std::vector<ServiceId>> parse_peers(const std::string& list, std::string* error) {
  std::vector<ServiceId> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    auto id = service_from_name(item);
    if (!id) {
      *error = "unknown service \"" + item + "\" in --peers";
      return std::nullopt;
    }
    out.push_back(*id);
  }
  return out;
}

void install_shutdown_handlers() {
  std::signal(SIGINT, on_shutdown_signal);
  std::signal(SIGTERM, on_shutdown_signal);
}

bool shutdown_requested() { return g_shutdown != 0; }

int service_main(int argc, char** argv, ServiceId id, const std::string& summary,
                 const std::function<void(cli::Args&)>& add_options,
                 const std::function<int(const ServiceContext&)>& body, const OptionsHook& finish_options) {
  ServiceOptions opt;
  opt.qos_file = default_qos_file();
  const std::string program = "entourage-" + std::string(to_string(id.role == Role::kMeso ? ServiceId{Role::kMeso, 0} : id));
  cli::Args args(program, summary);
  args.option("scenario", "FILE", "scenario file (Protocol Buffers text format); required", &opt.scenario_path);
  args.option("domain", "ID", "DDS domain id, 0-232 (default 0)", &opt.domain);
  args.option("qos", "FILE", "QoS profile file (default $ENTOURAGE_QOS or the build tree's copy)", &opt.qos_file);
  args.option("seed", "N", "random seed (default: the scenario's)", &opt.seed);
  args.option("mode", "MODE", "lockstep or realtime (default lockstep)", &opt.mode);
  args.option("peers", "LIST", "services taking part (default ego,generator,micro,meso,director,recorder)",
              &opt.peers);
  args.option("log-level", "LEVEL", "trace, debug, info, warn, error (default info)", &opt.log_level);
  args.option("discovery-timeout", "SECONDS", "give up waiting for the peers after this (default 60)",
              &opt.discovery_timeout_s);
  if (add_options) add_options(args);
  if (const auto rc = args.parse_or_exit(argc, argv)) return *rc;
  std::string error;
  if (opt.scenario_path.empty()) error = "--scenario is required";
  if (opt.mode == "lockstep") {
    opt.time_mode = TimeMode::kLockstep;
  } else if (opt.mode == "realtime") {
    opt.time_mode = TimeMode::kRealtime;
  } else if (error.empty()) {
    error = "--mode must be lockstep or realtime";
  }
  if ((opt.domain < 0 || opt.domain > kMaxDomainId) && error.empty()) error = "--domain must be in 0-232";
  if (auto peers = parse_peers(opt.peers, &error)) opt.peer_ids = *peers;
  if (error.empty() && finish_options) {
    if (auto e = finish_options(&id)) error = *e;
  }
  if (!error.empty()) {
    std::cerr << program << ": " << error << "\n";
    return 2;
  }

  ServiceContext ctx;
  ctx.id = id;
  ctx.options = opt;
  ctx.scenario = scenario::load_file(opt.scenario_path);
  if (!ctx.scenario.ok()) {
    for (const auto& p : ctx.scenario.problems) std::cerr << p.to_string() << "\n";
    std::cerr << program << ": the scenario has " << ctx.scenario.problems.size() << " problem(s)\n";
    return 2;
  }
  ctx.seed = opt.seed != 0 ? opt.seed : ctx.scenario.config.seed;

  auto logger = spdlog::stderr_color_mt(to_string(id));
  logger->set_pattern("[%H:%M:%S.%e] [%n] [%^%l%$] %v");
  logger->set_level(spdlog::level::from_str(opt.log_level));
  spdlog::set_default_logger(logger);
  if (const std::string w = ephemeral_clash_here(opt.domain); !w.empty()) spdlog::warn("{}", w);
  install_shutdown_handlers();
  try {
    return body(ctx);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}

StatusReporter::StatusReporter(Node& node, ServiceId id)
    : writer_(node.writer<msg::ServiceStatusPubSubType>(Topic::kServiceStatus)) {
  status_.service(id.code());
  status_.name(to_string(id));
  status_.pid(static_cast<uint32_t>(::getpid()));
  status_.state(static_cast<uint8_t>(ServiceState::kStarting));
}

void StatusReporter::set_state(ServiceState s, const std::string& detail) {
  status_.state(static_cast<uint8_t>(s));
  status_.detail(detail);
  publish();
}

void StatusReporter::step_done(Step step, double compute_ms, bool late) {
  status_.last_step(step);
  ++steps_;
  total_ms_ += compute_ms;
  status_.mean_step_ms(total_ms_ / static_cast<double>(steps_));
  if (compute_ms > status_.max_step_ms()) status_.max_step_ms(compute_ms);
  if (late) status_.late_steps(status_.late_steps() + 1);
}

void StatusReporter::set_counters(std::uint64_t bad_samples, std::uint64_t duplicate_handoffs) {
  status_.bad_samples(static_cast<uint32_t>(bad_samples));
  status_.duplicate_handoffs(static_cast<uint32_t>(duplicate_handoffs));
}

void StatusReporter::set_detail(const std::string& detail) { status_.detail(detail.substr(0, 160)); }

void StatusReporter::publish_if_due() {
  if (std::chrono::steady_clock::now() - last_publish_ >= kStatusPeriod) publish();
}

void StatusReporter::publish() {
  writer_.write(status_);
  last_publish_ = std::chrono::steady_clock::now();
}

bool wait_for_discovery(const Node& node, ServiceId self, const std::vector<ServiceId>& peers,
                        StatusReporter& status, double timeout_s) {
  const auto t0 = std::chrono::steady_clock::now();
  while (!shutdown_requested()) {
    const std::string lacking = lacking_matches(node, self, peers);
    if (lacking.empty()) {
      status.set_state(ServiceState::kReady);
      spdlog::info("discovered all peers");
      return true;
    }
    if (ms_since(t0) > timeout_s * 1000.0) {
      spdlog::error("discovery timed out after {} s; still missing:{}", timeout_s, lacking);
      status.set_state(ServiceState::kFailed, "discovery timed out:" + lacking);
      return false;
    }
    status.set_detail("waiting for discovery:" + lacking);
    status.publish_if_due();
    std::this_thread::sleep_for(kDiscoveryPoll);
  }
  return false;
}

TopicMask needed_topics(Role role) {
  const TopicMask world = mask_of(Topic::kEgoState) | mask_of(Topic::kVehicleState);
  switch (role) {
    case Role::kEgo: return mask_of(Topic::kVehicleState);
    case Role::kDirector: return world;
    case Role::kGenerator: return world | mask_of(Topic::kHandoff);
    // Every command of step k-1 is here before step k: it is applied at that step boundary.
    case Role::kMicro:
    case Role::kMeso: return world | mask_of(Topic::kHandoff) | mask_of(Topic::kActorCommand);
    case Role::kRecorder:
      return world | mask_of(Topic::kHandoff) | mask_of(Topic::kPlayStatus) | mask_of(Topic::kActorCommand);
    default: return 0;
  }
}

void run_step_loop(const ServiceContext& ctx, Inbox& inbox, const Writer<msg::StepDonePubSubType>& done_writer,
                   StatusReporter& status, const std::function<TopicCounts(Step)>& compute,
                   const std::function<std::uint32_t()>& owned,
                   const std::function<void(msg::StepDone&)>& complete_report) {
  const bool lockstep = ctx.options.time_mode == TimeMode::kLockstep;
  const TopicMask needed = needed_topics(ctx.id.role);
  std::optional<Step> first;
  Step k = 0;
  auto waiting_since = std::chrono::steady_clock::now();
  status.set_state(ServiceState::kRunning);
  while (!shutdown_requested()) {
    status.publish_if_due();
    if (!first) {
      // Start at the oldest ego state here: step 0 in a run started by the launcher, the present
      // step when joining a simulator that is already driving.
      inbox.wait([](const Inbox& in) { return in.newest_ego_step_locked().has_value(); }, kWaitSlice);
      if (auto newest = inbox.newest_ego_step()) {
        first = *newest;
        for (Step s = *newest; s > 0 && inbox.has_ego(s - 1); --s) first = s - 1;
        k = *first;
      }
      continue;
    }
    const bool start = k == *first;
    const bool ready = inbox.wait(
        [&](const Inbox& in) {
          return in.has_ego_locked(k) && (!lockstep || start || in.complete_locked(k - 1, needed));
        },
        kWaitSlice);
    if (!ready) {
      if (lockstep && std::chrono::steady_clock::now() - waiting_since > kStallReport) {
        spdlog::warn("step {} still waiting for step {} of:{}", k, k - 1, inbox.missing(k - 1, needed));
        waiting_since = std::chrono::steady_clock::now();
      }
      continue;
    }
    const bool late = !start && !inbox.complete(k - 1, needed);
    const auto t0 = std::chrono::steady_clock::now();
    const TopicCounts written = compute(k);
    const double compute_ms = ms_since(t0);
    msg::StepDone report = make_step_done(ctx.id, k, written, owned());
    if (complete_report) complete_report(report);
    done_writer.write(report);
    status.step_done(k, compute_ms, late);
    if (k > 0) inbox.forget_before(k - 1);
    waiting_since = std::chrono::steady_clock::now();
    ++k;
  }
  status.set_state(ServiceState::kFinished);
}

}  // namespace entourage::dds
