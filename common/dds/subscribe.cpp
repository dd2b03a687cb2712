#include "entourage_msg/EgoStatePubSubTypes.h"
#include "entourage_msg/HandoffPubSubTypes.h"
#include "entourage_msg/PlayStatusPubSubTypes.h"
#include "entourage_msg/ServiceStatusPubSubTypes.h"
#include "entourage_msg/StepDonePubSubTypes.h"
#include "entourage_msg/VehicleStatePubSubTypes.h"

#include "dds/region_shell.hpp"

namespace entourage::dds {

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
  node.reader<msg::StepDonePubSubType>(Topic::kStepDone, [&inbox](const msg::StepDone& m) { inbox.add(m); });
  node.reader<msg::ServiceStatusPubSubType>(Topic::kServiceStatus,
                                            [&inbox](const msg::ServiceStatus& m) { inbox.add(m); });
}

}  // namespace entourage::dds
