#pragma once
// Conversions between topic samples (idl/) and the model's types, and the checks a sample must
// pass before a core sees it (design invariant 5: a bad sample is logged, counted and dropped).

#include <optional>
#include <string>

#include "entourage_msg/ActorCommand.h"
#include "entourage_msg/EgoState.h"
#include "entourage_msg/Handoff.h"
#include "entourage_msg/PlayStatus.h"
#include "entourage_msg/StepDone.h"
#include "entourage_msg/VehicleState.h"

#include "dds/step_ledger.hpp"
#include "road/road.hpp"
#include "scenario/config.hpp"
#include "traffic/actor_control.hpp"
#include "traffic/handoff.hpp"
#include "traffic/step_io.hpp"
#include "traffic/world.hpp"

namespace entourage::dds {

EgoObservation from_msg(const msg::EgoState& m);
msg::EgoState to_msg(const EgoObservation& e, const Road& road);

ObservedVehicle from_msg(const msg::VehicleState& m);
msg::VehicleState to_msg(const VehicleReport& r, ServiceId owner, Step step, double time_s, const Road& road);
// The owner's record back from its message (what carries it forward: traffic/carried_states.hpp);
// to_msg of it gives the message again, bit for bit.
VehicleReport report_from_msg(const msg::VehicleState& m);

Handoff from_msg(const msg::Handoff& m);
msg::Handoff to_msg(const Handoff& h, double time_s, const Road& road);

ActorCommand from_msg(const msg::ActorCommand& m);
msg::ActorCommand to_msg(const ActorCommand& c, double time_s);

msg::StepDone make_step_done(ServiceId service, Step step, const TopicCounts& written, std::uint32_t owned);
TopicCounts counts_of(const msg::StepDone& m);

// What a sample's values may be for a scenario.
struct SampleLimits {
  int lanes_forward = 0;
  int lanes_backward = 0;
  int vehicle_types = 0;
  bool two_way = false;  // a vehicle may be in the oncoming lanes (overtaking on a rural road)
  double max_speed_mps = 100.0;
  double max_abs_accel_mps2 = 30.0;

  static SampleLimits of(const ScenarioConfig& sc);
};

// The reason a sample is refused, or nullopt if it is acceptable.
std::optional<std::string> check(const msg::EgoState& m, const SampleLimits& limits);
std::optional<std::string> check(const msg::VehicleState& m, const SampleLimits& limits);
std::optional<std::string> check(const msg::Handoff& m, const SampleLimits& limits);
std::optional<std::string> check(const msg::ActorCommand& m, const SampleLimits& limits);
// PlayStatus.phase runs from 0 (waiting) to 7 (failed): idl/PlayStatus.idl, the director's PlayPhase.
inline constexpr std::uint8_t kPlayPhases = 8;
std::optional<std::string> check(const msg::PlayStatus& m, const SampleLimits& limits);

}  // namespace entourage::dds
