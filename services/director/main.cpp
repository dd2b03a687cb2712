// entourage-director: the event director (see README.md).
#include "entourage_msg/ActorCommandPubSubTypes.h"
#include "entourage_msg/HandoffPubSubTypes.h"
#include "entourage_msg/PlayStatusPubSubTypes.h"

#include "dds/region_shell.hpp"
#include "director/core/director_core.hpp"

#include <spdlog/spdlog.h>

namespace entourage {
namespace {

static_assert(static_cast<int>(director::PlayPhase::kFailed) + 1 == dds::kPlayPhases,
              "PlayStatus.phase: the director's phases and what its readers accept");

msg::PlayStatus to_msg(const director::PlayReport& r, Step k, double time_s) {
  msg::PlayStatus m;
  m.play_id(r.play_id);
  m.step(k);
  m.time_s(time_s);
  m.name(r.name.substr(0, 64));
  m.phase(static_cast<uint8_t>(r.phase));
  m.ego_s_m(r.ego_s_m);
  m.trigger1_s_m(r.trigger1_s_m);
  m.trigger2_s_m(r.trigger2_s_m);
  m.estimated_start_time_s(r.estimated_start_time_s);
  m.actors(r.actors);
  m.created(r.created);
  m.cleared(r.cleared);
  m.position_error_m(r.position_error_m);
  m.speed_error_mps(r.speed_error_mps);
  m.detail(r.detail.substr(0, 160));
  return m;
}

int run(const dds::ServiceContext& ctx) {
  dds::Shell shell(ctx);
  const auto plays = shell.node.writer<msg::PlayStatusPubSubType>(dds::Topic::kPlayStatus);
  // The director's commands to its actors and the vehicles it creates (handed to meso).
  const auto commands = shell.node.writer<msg::ActorCommandPubSubType>(dds::Topic::kActorCommand);
  const auto handoffs = shell.node.writer<msg::HandoffPubSubType>(dds::Topic::kHandoff);
  const Road road(ctx.scenario.config.road);
  if (!shell.discover(ctx)) return 1;

  director::DirectorCore core(ctx.scenario.config, ctx.seed);
  dds::run_step_loop(
      ctx, shell.inbox, shell.done, shell.status,
      [&](Step k) {
        const StepInput in = dds::gather_inputs(k, shell.inbox, {});  // it publishes no vehicles
        const director::DirectorOutput out = core.step(in);
        const EgoObservation& ego = in.ego;
        dds::TopicCounts written{};
        for (const auto& r : out.reports) {
          plays.write(to_msg(r, k, ego.time_s));
          if (!r.detail.empty()) spdlog::info("play \"{}\": {}: {}", r.name, director::to_string(r.phase), r.detail);
          ++written[static_cast<std::size_t>(dds::Topic::kPlayStatus)];
        }
        for (const ActorCommand& c : out.commands) {
          commands.write(dds::to_msg(c, ego.time_s));
          ++written[static_cast<std::size_t>(dds::Topic::kActorCommand)];
        }
        for (const Handoff& h : out.births) {
          handoffs.write(dds::to_msg(h, ego.time_s, road));
          ++written[static_cast<std::size_t>(dds::Topic::kHandoff)];
        }
        shell.status.set_counters(shell.inbox.bad_samples(), 0);
        return written;
      },
      [] { return 0U; });
  return 0;
}

}  // namespace
}  // namespace entourage

int main(int argc, char** argv) {
  return entourage::dds::service_main(
      argc, argv, entourage::ServiceId{entourage::Role::kDirector, 0},
      "The event director: prepares the scenario's plays (casts vehicles as actors, moves them into place), "
      "hands them over to the script at trigger point 2, releases them afterwards, and reports each play's progress.",
      nullptr, entourage::run);
}
