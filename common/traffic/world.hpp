#pragma once
// The world as a service sees it at a step boundary: the ego and every vehicle as published by
// its owner. Cores read neighbours from this and never from another service's private state.

#include <cstdint>
#include <vector>

#include "core/ids.hpp"
#include "traffic/actor_control.hpp"
#include "traffic/lane_index.hpp"

namespace entourage {

struct EgoObservation {
  Step step = 0;
  double time_s = 0.0;
  Direction direction = Direction::kForward;
  int lane = 0;
  int target_lane = 0;
  std::uint8_t indicator = 0;
  double s_m = 0.0;
  double d_m = 0.0;
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 4.6;
  double width_m = 1.8;

  double progress_m() const { return sign(direction) * s_m; }
};

struct ObservedVehicle {
  VehicleId id = 0;
  ServiceId owner;
  Step step = 0;
  Direction direction = Direction::kForward;
  int lane = 0;
  int target_lane = 0;
  std::uint8_t type_index = 0;
  std::uint8_t indicator = 0;                      // 0 off, 1 left, 2 right
  ControlMode control = ControlMode::kAutonomous;  // an actor of a play when not autonomous
  double s_m = 0.0;
  double d_m = 0.0;
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 4.5;
  double width_m = 1.8;

  double progress_m() const { return sign(direction) * s_m; }
};

// Adds a vehicle to the lanes it occupies (both lanes while it changes lane).
// `signal`: the indicator, as Occupant::signal.
void add_to_index(LaneIndex& index, Direction dir, int lane, int target_lane, VehicleId id, double progress_m,
                  double speed_mps, double accel_mps2, double length_m, int signal = 0);
void add_to_index(LaneIndex& index, const ObservedVehicle& v);
void add_to_index(LaneIndex& index, const EgoObservation& ego);

}  // namespace entourage
