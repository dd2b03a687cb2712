#include "dds/topics.hpp"

namespace entourage::dds {

namespace {
constexpr std::array<TopicInfo, kTopicCount> kTopics{{
    {Topic::kEgoState, "entourage/ego_state", "EgoState", "entourage::msg::EgoState", "ego_state", true},
    {Topic::kVehicleState, "entourage/vehicle_state", "VehicleState", "entourage::msg::VehicleState", "vehicle_state",
     true},
    {Topic::kHandoff, "entourage/handoff", "Handoff", "entourage::msg::Handoff", "handoff", true},
    {Topic::kStepDone, "entourage/step_done", "StepDone", "entourage::msg::StepDone", "step_done", true},
    {Topic::kServiceStatus, "entourage/service_status", "ServiceStatus", "entourage::msg::ServiceStatus",
     "service_status", false},
    {Topic::kPlayStatus, "entourage/play_status", "PlayStatus", "entourage::msg::PlayStatus", "play_status", true},
    {Topic::kActorCommand, "entourage/actor_command", "ActorCommand", "entourage::msg::ActorCommand", "actor_command",
     true},
}};

// Bit t set: the role writes (or reads) topic t.
constexpr std::uint32_t bit(Topic t) { return 1U << static_cast<unsigned>(t); }
constexpr std::uint32_t kControl = bit(Topic::kStepDone) | bit(Topic::kServiceStatus);

std::uint32_t write_mask(Role r) {
  switch (r) {
    case Role::kEgo: return kControl | bit(Topic::kEgoState);
    case Role::kGenerator: return kControl | bit(Topic::kHandoff) | bit(Topic::kVehicleState);  // front zone
    case Role::kMicro:
    case Role::kMeso: return kControl | bit(Topic::kVehicleState) | bit(Topic::kHandoff);
    // The director commands the actors of its plays and hands the vehicles it creates to meso.
    case Role::kDirector: return kControl | bit(Topic::kPlayStatus) | bit(Topic::kActorCommand) | bit(Topic::kHandoff);
    case Role::kRecorder: return kControl;
    default: return 0;
  }
}

std::uint32_t read_mask(Role r) {
  const std::uint32_t world = bit(Topic::kEgoState) | bit(Topic::kVehicleState);
  switch (r) {
    case Role::kEgo: return kControl | bit(Topic::kVehicleState);
    // Vehicles leaving ahead, and the director's commands to them while they are in the front zone.
    case Role::kGenerator: return kControl | world | bit(Topic::kHandoff) | bit(Topic::kActorCommand);
    case Role::kDirector: return kControl | world;
    case Role::kMicro:
    case Role::kMeso: return kControl | world | bit(Topic::kHandoff) | bit(Topic::kActorCommand);
    case Role::kRecorder:
      return kControl | world | bit(Topic::kHandoff) | bit(Topic::kPlayStatus) | bit(Topic::kActorCommand);
    case Role::kLauncher: return kControl | bit(Topic::kEgoState);
    default: return 0;
  }
}
}  // namespace

const TopicInfo& info(Topic t) { return kTopics[static_cast<std::size_t>(t)]; }
const std::array<TopicInfo, kTopicCount>& all_topics() { return kTopics; }

bool writes(Role role, Topic t) { return (write_mask(role) & bit(t)) != 0; }
bool reads(Role role, Topic t) { return (read_mask(role) & bit(t)) != 0; }

int expected_writers(Topic t, const std::vector<ServiceId>& peers, ServiceId self) {
  int n = 0;
  for (const auto& p : peers) n += (p != self && writes(p.role, t)) ? 1 : 0;
  return n;
}

int expected_readers(Topic t, const std::vector<ServiceId>& peers, ServiceId self) {
  int n = 0;
  for (const auto& p : peers) n += (p != self && reads(p.role, t)) ? 1 : 0;
  return n;
}

}  // namespace entourage::dds
