#pragma once
// A simulated vehicle with its driver, as owned by one service at a time and carried whole in a
// handoff, so that a vehicle keeps its identity, lane, speed and driver across regions.

#include <cstdint>

#include "behaviour/car_following.hpp"
#include "behaviour/mobil.hpp"
#include "behaviour/model_registry.hpp"
#include "core/ids.hpp"

namespace entourage {

struct DriverParams {
  CarFollowingParams car_following;  // car_following.idm.desired_speed_mps is the desired speed
  LaneChangeModel lane_change = LaneChangeModel::kMobil;
  MobilParams mobil;
  double lane_change_duration_s = 4.0;
  double max_decel_mps2 = 8.0;        // physical braking limit of the vehicle
  double desired_speed_factor = 1.0;  // basic desired speed / the road's base speed limit
  bool keep_right = false;            // stays in the rightmost lane
  std::uint64_t rng_state = 0;        // the driver's own random stream (SmallRandom)

  double desired_speed_mps() const { return car_following.idm.desired_speed_mps; }
};

enum class LaneChangePhase : std::uint8_t { kNone = 0, kSignalling = 1, kMoving = 2 };

// A lane change in progress: the indicator is on for a while, then the vehicle moves laterally
// over duration_s with a smooth profile, occupying both lanes until it is done.
struct LaneChangeState {
  int from_lane = 0;
  int to_lane = 0;
  LaneChangePhase phase = LaneChangePhase::kNone;
  double phase_elapsed_s = 0.0;
  double duration_s = 4.0;
  double since_last_change_s = 1e9;

  bool active() const { return phase != LaneChangePhase::kNone; }
  bool moving() const { return phase == LaneChangePhase::kMoving; }
  // Lateral progress 0..1 along a quintic profile (zero lateral speed and acceleration at both ends).
  double lateral_fraction() const;
};

enum class Indicator : std::uint8_t { kOff = 0, kLeft = 1, kRight = 2 };

struct Vehicle {
  VehicleId id = 0;
  std::uint8_t type_index = 0;
  Direction direction = Direction::kForward;
  int lane = 0;  // the lane it is in; during a change, the lane it is leaving until the change ends
  double s_m = 0.0;
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 4.5;
  double width_m = 1.8;
  LaneChangeState lane_change;
  DriverParams driver;
  std::uint32_t handoff_sequence = 0;  // number of ownership changes so far

  // Position along the direction of travel: larger means further ahead, for both directions.
  double progress_m() const { return sign(direction) * s_m; }
  // The second lane it occupies while moving sideways (equal to `lane` otherwise). Published as
  // target_lane: a vehicle is in both `lane` and `target_lane`.
  int target_lane() const { return lane_change.moving() ? lane_change.to_lane : lane; }
  Indicator indicator() const;
};

}  // namespace entourage
