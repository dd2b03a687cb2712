#pragma once
// The inner region: microscopic simulation of every vehicle near the ego (thesis ch. 2.3, 3.2).
// Car following and lane changes come from common/behaviour through common/traffic/driving; the
// ego is a vehicle like any other to them. Vehicles arrive and leave by handoffs only.
//
// A step is five phases, each writing only its own output:
//   adopt     handoffs addressed to micro join the fleet; director commands reach their actors
//   perceive  the lane index from the fleet, the rest of the world at step-1 and the ego
//   decide    every driver's acceleration and lane change, from that same snapshot
//   move      commit the decisions and integrate over dt
//   hand off  vehicles beyond an inner border (plus hysteresis) go to meso, except one that is
//             overtaking: it stays until it is back in its own lane (meso does not drive in the
//             oncoming lane)

#include <cstdint>
#include <vector>

#include "road/road.hpp"
#include "road/window.hpp"
#include "scenario/config.hpp"
#include "traffic/driving.hpp"
#include "traffic/fleet.hpp"
#include "traffic/handoff.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/step_io.hpp"
#include "traffic/unseen_oncoming.hpp"

namespace entourage::micro {

struct Counters {
  std::uint64_t adopted = 0;
  std::uint64_t handed_out = 0;
  std::uint64_t lane_changes_started = 0;
  std::uint64_t mandatory_lane_changes = 0;
  std::uint64_t overtakings_started = 0;
  std::uint64_t overtakings_aborted = 0;
  std::uint64_t handoffs_deferred = 0;  // vehicle-steps kept beyond a border while overtaking
  std::uint64_t emergency_decisions = 0;  // vehicle-steps in the emergency regime
  std::uint64_t duplicate_handoffs = 0;
  std::uint64_t commands_applied = 0;  // director commands to vehicles owned here
};

class MicroCore {
 public:
  explicit MicroCore(const ScenarioConfig& scenario, ServiceId self = {Role::kMicro, 0});

  StepOutput step(const StepInput& in);

  const Fleet& fleet() const { return fleet_; }
  const Counters& counters() const { return counters_; }

 private:
  void adopt(const StepInput& in);
  void perceive(const StepInput& in);
  std::vector<Decision> decide() const;
  void move(const std::vector<Decision>& decisions);
  StepOutput hand_off(const StepInput& in);

  ScenarioConfig scenario_;
  ServiceId self_;
  Road road_;
  DrivingEnvironment env_;
  HandoffInbox inbox_;
  Fleet fleet_;
  LaneIndex index_;
  UnseenOncoming unseen_;  // the oncoming traffic beyond the window's front edge (traffic/unseen_oncoming.hpp)
  Counters counters_;
};

}  // namespace entourage::micro
