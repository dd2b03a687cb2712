#pragma once
// What every service shell holds: the inbox its readers fill, its participant with the readers of
// the topics its role reads, its health reports and its step reports. Members are declared so that
// the participant (whose callbacks fill the inbox) is destroyed before the inbox.

#include "entourage_msg/StepDonePubSubTypes.h"

#include "dds/inbox.hpp"
#include "dds/node.hpp"
#include "dds/runtime.hpp"

namespace entourage::dds {

struct Shell {
  // keep_refused: see Inbox (the recorder keeps bad samples).
  explicit Shell(const ServiceContext& ctx, bool keep_refused = false);

  // Waits until the peers are discovered (create the service's own writers first).
  bool discover(const ServiceContext& ctx);

  Inbox inbox;
  Node node;
  StatusReporter status;
  Writer<msg::StepDonePubSubType> done;
};

// Subscribes an inbox to the topics a service of `role` reads.
void subscribe(Node& node, Inbox& inbox, Role role);

}  // namespace entourage::dds
