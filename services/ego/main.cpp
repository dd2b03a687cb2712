// entourage-ego: the ego stand-in, driving in place of a simulator; also the lockstep clock
// (see README.md).
#include <thread>

#include "dds/region_shell.hpp"
#include "ego/core/ego_core.hpp"

#include <spdlog/spdlog.h>

namespace entourage {
namespace {

constexpr auto kWaitSlice = std::chrono::milliseconds(100);
// Real time: how long after the last step the ego waits for the others before it reports done.
constexpr auto kRealtimeFinalGrace = std::chrono::seconds(2);
constexpr auto kStallReport = std::chrono::seconds(10);

struct EgoOptions {
  double duration_s = -1.0;  // < 0: the scenario's
};

// Waits until every peer reports ready (so that none misses the first ego state).
bool wait_for_peers_ready(dds::Inbox& inbox, const dds::ServiceContext& ctx, dds::StatusReporter& status) {
  const auto t0 = std::chrono::steady_clock::now();
  auto all_ready = [&](const dds::Inbox& in) {
    for (const ServiceId& p : ctx.options.peer_ids) {
      if (p == ctx.id) continue;
      auto it = in.statuses_locked().find(p.code());
      if (it == in.statuses_locked().end()) return false;
      const auto state = static_cast<dds::ServiceState>(it->second.state());
      if (state != dds::ServiceState::kReady && state != dds::ServiceState::kRunning) return false;
    }
    return true;
  };
  while (!dds::shutdown_requested()) {
    if (inbox.wait(all_ready, kWaitSlice)) return true;
    status.publish_if_due();
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (waited > ctx.options.discovery_timeout_s) {
      spdlog::error("peers not ready after {} s", ctx.options.discovery_timeout_s);
      return false;
    }
  }
  return false;
}

int run(const dds::ServiceContext& ctx, const EgoOptions& eo) {
  const ScenarioConfig& sc = ctx.scenario.config;
  const Road road(sc.road);
  const bool lockstep = ctx.options.time_mode == dds::TimeMode::kLockstep;
  const dds::TopicMask needed = dds::needed_topics(Role::kEgo);
  dds::Shell shell(ctx);
  const auto egos = shell.node.writer<msg::EgoStatePubSubType>(dds::Topic::kEgoState);
  if (!shell.discover(ctx)) return 1;
  dds::Inbox& inbox = shell.inbox;
  dds::StatusReporter& status = shell.status;
  const auto& done = shell.done;
  if (!wait_for_peers_ready(inbox, ctx, status)) return dds::shutdown_requested() ? 0 : 1;

  ego::EgoCore core(sc, ctx.seed);
  const double duration = eo.duration_s >= 0.0 ? eo.duration_s : sc.duration_s;
  Step last = static_cast<Step>(std::llround(duration / sc.step_s));
  dds::TopicCounts one_state{};
  one_state[static_cast<std::size_t>(dds::Topic::kEgoState)] = 1;
  auto publish = [&](const EgoObservation& e) {
    egos.write(dds::to_msg(e, road));
    done.write(dds::make_step_done(ctx.id, e.step, one_state, 0));
  };

  status.set_state(dds::ServiceState::kRunning);
  spdlog::info("driving {} steps of {} s in {} mode", last, sc.step_s, ctx.options.mode);
  publish(core.initial());
  const auto t0 = std::chrono::steady_clock::now();
  auto waiting_since = t0;
  for (Step k = 1; k <= last && !dds::shutdown_requested(); ++k) {
    if (lockstep) {
      while (!inbox.wait([&](const dds::Inbox& in) { return in.complete_locked(k - 1, needed); }, kWaitSlice)) {
        if (dds::shutdown_requested()) break;
        status.publish_if_due();
        if (std::chrono::steady_clock::now() - waiting_since > kStallReport) {
          spdlog::warn("step {} still waiting for step {} of:{}", k, k - 1, inbox.missing(k - 1, needed));
          waiting_since = std::chrono::steady_clock::now();
        }
      }
    } else {
      std::this_thread::sleep_until(t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(static_cast<double>(k) * sc.step_s)));
    }
    if (dds::shutdown_requested()) break;
    const bool late = !inbox.complete(k - 1, needed);
    const auto c0 = std::chrono::steady_clock::now();
    std::vector<ObservedVehicle> world;
    for (const auto& m : inbox.take(k - 1).vehicles) world.push_back(dds::from_msg(m));
    std::sort(world.begin(), world.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    publish(core.step(k, world));
    status.step_done(k, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c0).count(), late);
    status.set_counters(inbox.bad_samples(), 0);
    status.publish_if_due();
    inbox.forget_before(k - 1);
    waiting_since = std::chrono::steady_clock::now();
    if (core.at_road_end()) {
      spdlog::warn("the ego reached the end of the road at step {}: the run ends here", k);
      last = k;
      break;
    }
  }
  // Let every peer finish the last step, so that the recording holds it whole.
  const auto final_deadline = std::chrono::steady_clock::now() + kRealtimeFinalGrace;
  while (!dds::shutdown_requested() &&
         !inbox.wait([&](const dds::Inbox& in) { return in.complete_locked(last, needed); }, kWaitSlice)) {
    if (!lockstep && std::chrono::steady_clock::now() > final_deadline) break;
    status.publish_if_due();
  }
  status.set_state(dds::ServiceState::kFinished, "drove to step " + std::to_string(last));
  spdlog::info("finished at step {}", last);
  while (!dds::shutdown_requested()) std::this_thread::sleep_for(kWaitSlice);
  return 0;
}

}  // namespace

int ego_main(int argc, char** argv) {
  EgoOptions eo;
  return dds::service_main(
      argc, argv, ServiceId{Role::kEgo, 0},
      "Drives the ego in place of a simulator (an IDM driver or a speed profile from the scenario) and publishes "
      "its state every step; in lockstep it is the clock that starts each step.",
      [&eo](cli::Args& args) {
        args.option("duration", "SECONDS", "simulated time to drive (default: the scenario's duration_s)",
                    &eo.duration_s);
      },
      [&eo](const dds::ServiceContext& ctx) { return run(ctx, eo); });
}

}  // namespace entourage

int main(int argc, char** argv) { return entourage::ego_main(argc, argv); }
