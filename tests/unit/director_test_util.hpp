#pragma once
// Helpers shared by the director's unit tests: a vehicle as the director sees it, a play with
// one lead role, a scenario with a cutter play, a role starting in a lane, the aim at its trigger
// point 2, and infinity (a time to collision never reached, a role a vehicle cannot play).

#include <limits>
#include <vector>

#include "core_test_util.hpp"
#include "director/core/play.hpp"
#include "director/core/stage.hpp"

namespace entourage::testing {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline ObservedVehicle vehicle(VehicleId id, double s, double speed, int lane = 0, Direction dir = Direction::kForward) {
  ObservedVehicle v;
  v.id = id;
  v.direction = dir;
  v.lane = v.target_lane = lane;
  v.s_m = s;
  v.speed_mps = speed;
  v.length_m = 4.5;
  return v;
}

// A role of the ego's (forward) direction that starts in `lane`: where and how fast matter only
// against vehicle types (ClearingSituation::types), which the tests give where they need them.
inline std::vector<director::Slot> role_starting_in(int lane) { return {{Direction::kForward, lane, 0.0, 0.0}}; }

// A play with one role: a car 40 m ahead of the ego at its speed; trigger points at 2 and 3 km.
inline PlayConfig lead_play() {
  PlayConfig p;
  p.id = 1;
  p.name = "lead";
  p.trigger1_s_m = 2000.0;
  p.trigger2_s_m = 3000.0;
  PlayRoleConfig lead;
  lead.name = "lead";
  lead.ahead_m = 40.0;
  lead.speed_mps = 0.0;  // the ego's speed
  p.roles = {lead};
  return p;
}

// The minimal scenario with one play: a cutter 12 m ahead of the ego in the lane to its left at
// the start (3 km, 40 s ahead at 25 m/s).
inline ScenarioConfig cutter_scenario() {
  ScenarioConfig sc = minimal_scenario();
  PlayConfig play = lead_play();
  play.roles[0].name = "cutter";
  play.roles[0].lane_offset = 1;
  play.roles[0].ahead_m = 12.0;
  sc.plays = {play};
  // The approach these tests' places and speeds were laid out for (the default since stop 66: 25 s).
  sc.director.beside_approach_s = 20.0;
  return sc;
}

// Aimed at the start: the ego at trigger point 2 at `speed_mps`, a minute from now.
inline director::Aim at_trigger2(const PlayConfig& p, double speed_mps) { return {60.0, p.trigger2_s_m, speed_mps, 0.0}; }

}  // namespace entourage::testing
