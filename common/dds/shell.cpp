#include "dds/shell.hpp"

#include "entourage_msg/ActorCommandPubSubTypes.h"
#include "entourage_msg/EgoStatePubSubTypes.h"
#include "entourage_msg/HandoffPubSubTypes.h"
#include "entourage_msg/PlayStatusPubSubTypes.h"
#include "entourage_msg/ServiceStatusPubSubTypes.h"
#include "entourage_msg/VehicleStatePubSubTypes.h"

namespace entourage::dds {

Shell::Shell(const ServiceContext& ctx, bool keep_refused)
    : inbox(ctx.options.peer_ids, ctx.id, SampleLimits::of(ctx.scenario.config), keep_refused),
      node(ctx.options.domain, ctx.options.qos_file, to_string(ctx.id)),
      status(node, ctx.id),
      done(node.writer<msg::StepDonePubSubType>(Topic::kStepDone)) {
  inbox.carry_states(ctx.scenario.config.road, ctx.scenario.config.step_s);
  subscribe(node, inbox, ctx.id.role);
}

bool Shell::discover(const ServiceContext& ctx) {
  return wait_for_discovery(node, ctx.id, ctx.options.peer_ids, status, ctx.options.discovery_timeout_s);
}

void subscribe(Node& node, Inbox& inbox, Role role) {
  if (reads(role, Topic::kEgoState)) {
    node.reader<msg::EgoStatePubSubType>(Topic::kEgoState, [&inbox](const msg::EgoState& m) { inbox.add(m); });
  }
  if (reads(role, Topic::kVehicleState)) {
    node.reader<msg::VehicleStatePubSubType>(Topic::kVehicleState,
                                             [&inbox](const msg::VehicleState& m) { inbox.add(m); });
  }
  if (reads(role, Topic::kHandoff)) {
    node.reader<msg::HandoffPubSubType>(Topic::kHandoff, [&inbox](const msg::Handoff& m) { inbox.add(m); });
  }
  if (reads(role, Topic::kPlayStatus)) {
    node.reader<msg::PlayStatusPubSubType>(Topic::kPlayStatus, [&inbox](const msg::PlayStatus& m) { inbox.add(m); });
  }
  if (reads(role, Topic::kActorCommand)) {
    node.reader<msg::ActorCommandPubSubType>(Topic::kActorCommand,
                                             [&inbox](const msg::ActorCommand& m) { inbox.add(m); });
  }
  node.reader<msg::StepDonePubSubType>(Topic::kStepDone, [&inbox](const msg::StepDone& m) { inbox.add(m); });
  node.reader<msg::ServiceStatusPubSubType>(Topic::kServiceStatus,
                                            [&inbox](const msg::ServiceStatus& m) { inbox.add(m); });
}

}  // namespace entourage::dds
