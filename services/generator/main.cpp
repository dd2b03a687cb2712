// entourage-generator: vehicle generation at the edges of the moving window (see README.md).
#include "dds/region_shell.hpp"
#include "generator/core/generator_core.hpp"

#include <spdlog/spdlog.h>

namespace entourage {
namespace {

int run(const dds::ServiceContext& ctx) {
  const ScenarioConfig& sc = ctx.scenario.config;
  const Road road(sc.road);
  dds::Inbox inbox(ctx.options.peer_ids, ctx.id, dds::SampleLimits::of(sc));
  dds::Node node(ctx.options.domain, ctx.options.qos_file, to_string(ctx.id));
  dds::subscribe(node, inbox, ctx.id.role);
  const auto handoffs = node.writer<msg::HandoffPubSubType>(dds::Topic::kHandoff);
  const auto done = node.writer<msg::StepDonePubSubType>(dds::Topic::kStepDone);
  dds::StatusReporter status(node, ctx.id);
  if (!dds::wait_for_discovery(node, ctx.id, ctx.options.peer_ids, status, ctx.options.discovery_timeout_s)) return 1;

  generator::GeneratorCore core(sc, Random::derived(ctx.seed, static_cast<std::uint64_t>(Role::kGenerator)).next_u64());
  dds::run_step_loop(
      ctx, inbox, done, status,
      [&](Step k) {
        const StepOutput out = core.step(dds::gather_inputs(k, inbox, {}));
        status.set_counters(inbox.bad_samples(), 0);
        status.set_detail("queued at the edges: " + std::to_string(core.queued()));
        dds::TopicCounts written{};
        for (const Handoff& h : out.handoffs) {
          handoffs.write(dds::to_msg(h, static_cast<double>(k) * sc.step_s, road));
          ++written[static_cast<std::size_t>(dds::Topic::kHandoff)];
        }
        return written;
      },
      [] { return 0U; });
  const auto& c = core.counters();
  spdlog::info("generated {} vehicles ({} by {} fills, {} of {} edge arrivals), {} still queued", c.filled + c.placed,
               c.filled, c.fills, c.placed, c.arrivals, core.queued());
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) {
  return entourage::dds::service_main(
      argc, argv, entourage::ServiceId{entourage::Role::kGenerator, 0},
      "Creates vehicles at the edges of the window moving with the ego, at the demanded flow, and hands them to "
      "the region that owns the road there.",
      nullptr, entourage::run);
}
