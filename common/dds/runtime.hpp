#pragma once
// What every service shell shares: its command-line options, its main() frame (arguments,
// scenario, logging, clear errors and exit codes), shutdown on SIGINT/SIGTERM, health reports
// (ServiceStatus), waiting for discovery, and the per-step loop of the services that compute one
// step per ego state.
//
// Exit codes: 0 clean stop, 1 runtime failure, 2 bad command line or scenario.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "dds/inbox.hpp"
#include "entourage_msg/ServiceStatusPubSubTypes.h"
#include "entourage_msg/StepDonePubSubTypes.h"
#include "dds/node.hpp"
#include "scenario/loader.hpp"

namespace entourage::dds {

enum class TimeMode { kLockstep, kRealtime };

struct ServiceOptions {
  std::string scenario_path;
  int domain = 0;
  std::string qos_file;
  std::uint64_t seed = 0;  // 0: the scenario's seed
  std::string mode = "lockstep";
  std::string peers = "ego,generator,micro,meso,director,recorder";
  std::string log_level = "info";
  double discovery_timeout_s = 60.0;

  TimeMode time_mode = TimeMode::kLockstep;
  std::vector<ServiceId> peer_ids;
};

// The default QoS file (the build tree's copy) unless ENTOURAGE_QOS is set.
std::string default_qos_file();
std::optional<std::vector<ServiceId>> parse_peers(const std::string& list, std::string* error);

struct ServiceContext {
  ServiceId id;
  ServiceOptions options;
  scenario::Loaded scenario;
  std::uint64_t seed = 0;  // the effective seed
};

// Runs a service: parses the common options and the service's own (add_options), lets
// `finish_options` check them and settle the service id (e.g. which meso instance), loads and
// checks the scenario, sets up logging, then calls body(). Exceptions become exit code 1.
using OptionsHook = std::function<std::optional<std::string>(ServiceId* id)>;
int service_main(int argc, char** argv, ServiceId id, const std::string& summary,
                 const std::function<void(cli::Args&)>& add_options,
                 const std::function<int(const ServiceContext&)>& body, const OptionsHook& finish_options = {});

// SIGINT / SIGTERM ask the service to stop; the flag is the only state a signal handler may touch.
void install_shutdown_handlers();
bool shutdown_requested();

enum class ServiceState : std::uint8_t { kStarting = 1, kReady = 2, kRunning = 3, kFinished = 4, kFailed = 5 };

// Publishes the service's health at most once a second (and at once on a change of state).
class StatusReporter {
 public:
  StatusReporter(Node& node, ServiceId id);

  void set_state(ServiceState s, const std::string& detail = "");
  void step_done(Step step, double compute_ms, bool late);
  void set_counters(std::uint64_t bad_samples, std::uint64_t duplicate_handoffs);
  void set_detail(const std::string& detail);
  void publish_if_due();
  void publish();

 private:
  Writer<msg::ServiceStatusPubSubType> writer_;
  msg::ServiceStatus status_;
  double total_ms_ = 0.0;
  std::uint64_t steps_ = 0;
  std::chrono::steady_clock::time_point last_publish_{};
};

// Waits until every reader of this service has matched the writers of its peers and every writer
// their readers (discovery), reporting progress in the status detail. False on timeout/shutdown.
bool wait_for_discovery(const Node& node, ServiceId self, const std::vector<ServiceId>& peers,
                        StatusReporter& status, double timeout_s);

// The topics whose samples a service of `role` needs complete before it computes a step.
TopicMask needed_topics(Role role);

// The step loop of a service that computes one step per ego state (generator, micro, meso,
// director). For each step k, once the ego state of k is here and (in lockstep) every peer has
// completed k-1 with all its samples, calls compute(k), which publishes the step's samples and
// returns how many it wrote per topic; then reports the step done (`complete_report`, if given,
// adds to the report what the service's readers need besides the counts). Returns at shutdown.
void run_step_loop(const ServiceContext& ctx, Inbox& inbox, const Writer<msg::StepDonePubSubType>& done_writer,
                   StatusReporter& status, const std::function<TopicCounts(Step)>& compute,
                   const std::function<std::uint32_t()>& owned,
                   const std::function<void(msg::StepDone&)>& complete_report = {});

}  // namespace entourage::dds
