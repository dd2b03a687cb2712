#pragma once
// A simulated vehicle with its driver, as owned by one service at a time and carried whole in a
// handoff, so that a vehicle keeps its identity, lane, speed and driver across regions.

#include <cstdint>

#include "behaviour/car_following.hpp"
#include "behaviour/hdm.hpp"
#include "behaviour/mobil.hpp"
#include "behaviour/model_registry.hpp"
#include "traffic/actor_control.hpp"
#include "core/ids.hpp"

namespace entourage {

struct DriverParams {
  // car_following.idm.desired_speed_mps is the driver's basic desired speed (for the road's
  // reference conditions); speed adaptation (traffic/speed_sections.hpp) turns it into the
  // desired speed at each place.
  CarFollowingParams car_following;
  LaneChangeModel lane_change = LaneChangeModel::kMobil;
  MobilParams mobil;
  double lane_change_duration_s = 4.0;
  double max_decel_mps2 = 8.0;             // physical braking limit of the vehicle
  double desired_speed_median_mps = 0.0;   // median of the type's basic desired speeds (0: own)
  bool keep_right = false;                 // stays in the rightmost lane
  std::uint64_t rng_state = 0;             // the driver's own random stream (SmallRandom)

  double desired_speed_mps() const { return car_following.idm.desired_speed_mps; }
  double basic_median_mps() const {
    return desired_speed_median_mps > 0.0 ? desired_speed_median_mps : desired_speed_mps();
  }
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
  // Time until the driver next weighs a discretionary change (DrivingRules::decision_interval_s).
  double decision_wait_s = 0.0;

  bool active() const { return phase != LaneChangePhase::kNone; }
  bool moving() const { return phase == LaneChangePhase::kMoving; }
  // Lateral progress 0..1 along a quintic profile (zero lateral speed and acceleration at both ends).
  double lateral_fraction() const;
  // Time until the lateral movement ends (0 when not moving sideways).
  double moving_left_s() const;
};

// The second lane a vehicle in `lane` occupies: the one it moves into while it moves sideways.
inline int target_lane_of(const LaneChangeState& lc, int lane) { return lc.moving() ? lc.to_lane : lane; }

enum class Indicator : std::uint8_t { kOff = 0, kLeft = 1, kRight = 2 };

// An overtaking on a two-lane road (behaviour/overtaking.hpp, traffic/overtaking_manoeuvre.hpp).
// The lateral movements out and back are lane changes between the own lane and the oncoming lane
// (lane numbers >= the direction's lane count are the oncoming carriageway, see lane_slot.hpp).
enum class OvertakingPhase : std::uint8_t {
  kNone = 0,
  kPassing = 1,   // moving out or in the oncoming lane, gaining on the overtaken vehicles
  kReturning = 2, // moving back in front of them
  kAborting = 3,  // braking to return behind them
};

struct OvertakingState {
  OvertakingPhase phase = OvertakingPhase::kNone;
  std::uint8_t kind = 0;                 // OvertakingKind of the accepted decision
  VehicleId overtaken = 0;               // the last (front-most) vehicle to pass
  double elapsed_s = 0.0;                // since the overtaking started
  double next_decision_s = 0.0;          // time until an accelerated overtaking is reconsidered
  std::uint32_t started = 0;             // overtakings this driver has started
  std::uint32_t aborted = 0;             // of which aborted

  bool active() const { return phase != OvertakingPhase::kNone; }
};

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
  OvertakingState overtaking;
  // A lane the vehicle must reach (a play asks for it); -1: none. Closed lanes ask by themselves.
  int requested_lane = -1;
  ActorControl control;  // what the event director asks of it (autonomous unless cast in a play)
  DriverParams driver;
  HdmErrors hdm_errors;                // the driver's current estimation errors (HDM)
  HdmMemory hdm_memory;                // its recent decisions, for the reaction time (not handed over)
  std::uint32_t handoff_sequence = 0;  // number of ownership changes so far

  // Position along the direction of travel: larger means further ahead, for both directions.
  double progress_m() const { return sign(direction) * s_m; }
  // The second lane it occupies while moving sideways (equal to `lane` otherwise). Published as
  // target_lane: a vehicle is in both `lane` and `target_lane`.
  int target_lane() const { return target_lane_of(lane_change, lane); }
  Indicator indicator() const;
};

// The indicator of a vehicle with lane change `lc`: the side it changes to, or else what a
// controlled actor's script shows (`control_indicator`), or off.
Indicator indicator_of(const LaneChangeState& lc, ControlMode mode, Indicator control_indicator);

}  // namespace entourage
