// entourage-generator: vehicle generation at the edges of the moving window (see README.md).
#include "dds/region_shell.hpp"
#include "generator/core/generator_core.hpp"

#include <spdlog/spdlog.h>

namespace entourage {
namespace {

int run(const dds::ServiceContext& ctx) {
  const ScenarioConfig& sc = ctx.scenario.config;
  const Road road(sc.road);
  dds::Shell shell(ctx);
  dds::RegionPublisher publisher(shell.node, ctx.id, road, dds::SampleLimits::of(sc));
  // Observing the demand's stream takes a second or two: done before reporting ready.
  generator::GeneratorCore core(sc, generator_seed(ctx.seed));
  for (Direction d : {Direction::kForward, Direction::kBackward}) {
    const ObservedStream& st = core.stream(d);
    if (st.empty()) continue;
    spdlog::info("stream {}: {:.0f} veh/h (the snapshots carried {:.0f}), density {:.2f} veh/km, space-mean speed "
                 "{:.1f} km/h, {} platoons observed",
                 to_string(d), st.flow_veh_per_s() * 3600.0, st.sample_flow_per_s() * 3600.0,
                 st.density_per_m() * 1000.0, st.mean_speed_mps() * 3.6, st.platoons().size());
  }
  if (!shell.discover(ctx)) return 1;

  dds::run_step_loop(
      ctx, shell.inbox, shell.done, shell.status,
      [&](Step k) {
        const StepOutput out = core.step(dds::gather_inputs(k, shell.inbox, publisher.own()));
        shell.status.set_counters(shell.inbox.bad_samples(), 0);
        shell.status.set_detail("queued at the edges: " + std::to_string(core.queued()));
        return publisher.publish(k, static_cast<double>(k) * sc.step_s, out);
      },
      [&core] { return static_cast<std::uint32_t>(core.front_zone().size()); });
  const auto& c = core.counters();
  spdlog::info(
      "generated {} vehicles: {} by {} fills ({} left out for lack of room, {} overlapping another in the observed "
      "stream), {} at the edges from {} platoon arrivals ({} from behind at their leader's speed, {} platoons dropped, "
      "{} still queued)",
      c.filled + c.placed, c.filled, c.fills, c.fill_skipped, c.fill_overlapping, c.placed, c.arrivals,
      c.at_leader_speed, c.dropped, core.queued());
  spdlog::info("front zone: {} vehicles joined it, {} left it far ahead, {} made way for a slow platoon; director "
               "commands applied {}",
               c.ahead, c.left_ahead, c.made_way, c.commands_applied);
  spdlog::info("platoons arrived / their vehicles / vehicles placed: from behind {}/{}/{}, from ahead {}/{}/{}, "
               "oncoming {}/{}/{}",
               c.arrivals_at[0], c.members_at[0], c.placed_at[0], c.arrivals_at[1], c.members_at[1], c.placed_at[1],
               c.arrivals_at[2], c.members_at[2], c.placed_at[2]);
  spdlog::info("platoons expected at the moving-observer rates / after the regulation: from behind {:.1f}/{:.1f}, "
               "from ahead {:.1f}/{:.1f}, oncoming {:.1f}/{:.1f}",
               c.expected_plain_at[0], c.expected_regulated_at[0], c.expected_plain_at[1], c.expected_regulated_at[1],
               c.expected_plain_at[2], c.expected_regulated_at[2]);
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
