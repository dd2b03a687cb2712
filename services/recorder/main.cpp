// entourage-recorder: writes every simulation topic to an MCAP file (see README.md).
#include <filesystem>

#include "dds/region_shell.hpp"
#include "recording/recording.hpp"

#include <spdlog/spdlog.h>

namespace entourage {
namespace {

constexpr auto kWaitSlice = std::chrono::milliseconds(100);
// Real time: a step still incomplete when the ego is this many steps further is written as it is
// (samples arriving later are written with a later step, never dropped).
constexpr Step kRealtimeLagSteps = 20;

struct RecorderOptions {
  std::string out;
};

recording::StepSamples collect(dds::Inbox& inbox, Step step, double step_s) {
  recording::StepSamples s;
  s.step = step;
  s.time_s = static_cast<double>(step) * step_s;
  s.ego = inbox.ego(step);
  dds::Bucket b = inbox.take(step);
  s.vehicles = std::move(b.vehicles);
  s.handoffs = std::move(b.handoffs);
  s.plays = std::move(b.plays);
  s.commands = std::move(b.commands);
  s.done = std::move(b.done);
  return s;
}

int run(const dds::ServiceContext& ctx, const RecorderOptions& ro) {
  const ScenarioConfig& sc = ctx.scenario.config;
  const bool lockstep = ctx.options.time_mode == dds::TimeMode::kLockstep;
  const dds::TopicMask needed = dds::needed_topics(Role::kRecorder);

  recording::RecordingInfo info;
  info.scenario_name = sc.name;
  info.scenario_file = std::filesystem::path(ctx.options.scenario_path).filename().string();
  info.scenario_text = ctx.scenario.text;
  info.seed = ctx.seed;
  info.mode = ctx.options.mode;
  info.step_s = sc.step_s;
  info.peers = ctx.options.peers;
  recording::RecordingWriter writer;
  if (!writer.open(ro.out, info)) {
    spdlog::error("{}", writer.error());
    return 1;
  }

  dds::Shell shell(ctx, /*keep_refused=*/true);
  if (!shell.discover(ctx)) return 1;
  dds::Inbox& inbox = shell.inbox;
  dds::StatusReporter& status = shell.status;
  status.set_state(dds::ServiceState::kRunning);

  Step next = 0;
  std::uint64_t incomplete = 0;
  std::uint64_t late_writes = 0;
  while (!dds::shutdown_requested()) {
    status.publish_if_due();
    const bool ready = inbox.wait(
        [&](const dds::Inbox& in) {
          if (in.complete_locked(next, needed)) return true;
          const auto newest = in.newest_ego_step_locked();
          return !lockstep && newest && *newest >= next + kRealtimeLagSteps;
        },
        kWaitSlice);
    if (!ready) continue;
    if (!inbox.complete(next, needed)) ++incomplete;
    for (Step late : inbox.steps_with_samples_before(next)) {  // real time: arrived after their step was written
      writer.write_step(collect(inbox, late, sc.step_s));
      ++late_writes;
    }
    writer.write_step(collect(inbox, next, sc.step_s));
    shell.done.write(dds::make_step_done(ctx.id, next, {}, 0));
    status.step_done(next, 0.0, false);
    status.set_counters(inbox.bad_samples(), 0);
    inbox.forget_bookkeeping_before(next);
    ++next;
  }
  // Stopping: whatever has arrived for later steps is written too.
  for (Step s = next; inbox.newest_ego_step() && s <= *inbox.newest_ego_step(); ++s) {
    writer.write_step(collect(inbox, s, sc.step_s));
  }
  if (!writer.close()) {
    spdlog::error("{}", writer.error());
    return 1;
  }
  spdlog::info("wrote {} messages for {} steps to {} ({} steps written incomplete, {} late batches)", writer.messages(),
               next, ro.out, incomplete, late_writes);
  return 0;
}

}  // namespace

int recorder_main(int argc, char** argv) {
  RecorderOptions ro;
  return dds::service_main(
      argc, argv, ServiceId{Role::kRecorder, 0},
      "Records every simulation topic (ego and vehicle states, handoffs, play status, director commands, step "
      "reports) to an MCAP file, each sample as its CDR bytes with the IDL of its type as schema.",
      [&ro](cli::Args& args) { args.option("out", "FILE", "the MCAP file to write; required", &ro.out); },
      [&ro](const dds::ServiceContext& ctx) { return run(ctx, ro); },
      [&ro](ServiceId*) -> std::optional<std::string> {
        if (ro.out.empty()) return std::string("--out is required");
        return std::nullopt;
      });
}

}  // namespace entourage

int main(int argc, char** argv) { return entourage::recorder_main(argc, argv); }
