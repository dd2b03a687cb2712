#pragma once
// A scenario resolved into plain SI structs: defaults applied, km/h and veh/h converted, names
// looked up. Service cores take these, never the protobuf messages, so a core does not depend on
// the file format and every conversion happens once, here.

#include <cstdint>
#include <string>
#include <vector>

#include "behaviour/hdm_params.hpp"
#include "behaviour/overtaking.hpp"
#include "behaviour/speed_adaptation.hpp"
#include "core/ids.hpp"

namespace entourage {

struct NormalDist {
  double mean = 0.0;
  double sd = 0.0;
  double min = 0.0;
  double max = 0.0;
};

struct SegmentConfig {
  double length_m = 0.0;
  double curvature_per_m = 0.0;
};

struct SpeedZoneConfig {
  double start_m = 0.0;
  double end_m = 0.0;
  double limit_mps = 0.0;
};

// A stretch where drivers of the given directions do not start overtakings (e.g. a solid centre
// line). On a rural road the oncoming lane is used only outside such zones.
struct OvertakingRestrictionConfig {
  double start_m = 0.0;
  double end_m = 0.0;
  bool forward = true;
  bool backward = true;

  bool applies_to(Direction d) const { return d == Direction::kForward ? forward : backward; }
};

// A lane that is closed over [start_m, end_m] (road works, a lane drop): its drivers must change
// lane before they reach it, and nobody changes into it.
struct LaneClosureConfig {
  Direction direction = Direction::kForward;
  int lane = 0;
  double start_m = 0.0;
  double end_m = 0.0;
};

enum class RoadKind { kFreeway, kRural };

struct RoadConfig {
  RoadKind kind = RoadKind::kFreeway;
  double length_m = 0.0;
  int lanes_forward = 2;
  int lanes_backward = 2;
  double lane_width_m = 3.5;
  double median_width_m = 0.0;
  double speed_limit_mps = 0.0;
  std::vector<SegmentConfig> segments;
  std::vector<SpeedZoneConfig> speed_zones;
  std::vector<OvertakingRestrictionConfig> no_overtaking;
  std::vector<LaneClosureConfig> lane_closures;
  // Lateral clearance from the inside of a curve to what blocks the view (trees, cuttings): sets
  // the sight distance in curves, sqrt(8 R clearance).
  double sight_clearance_m = 5.0;

  int lanes(Direction d) const { return d == Direction::kForward ? lanes_forward : lanes_backward; }
};

struct WindowConfig {
  double inner_ahead_m = 400.0;
  double inner_behind_m = 200.0;
  double outer_ahead_m = 600.0;
  double outer_behind_m = 400.0;
  double handoff_hysteresis_m = 10.0;
};

// Population of drivers of one vehicle type: each parameter drawn per driver.
struct DriverPopulation {
  std::string car_following = "idm";
  std::string lane_change = "mobil";
  NormalDist desired_speed_mps;
  NormalDist time_gap_s;
  NormalDist max_accel_mps2;
  NormalDist comfort_decel_mps2;
  NormalDist min_gap_m;
  double accel_exponent = 4.0;
  double beta = 1.35;
  double coolness = 0.0;  // the ACC model's c (behaviour/cah.hpp); 0 = off
  NormalDist politeness;
  double change_threshold_mps2 = 0.1;
  double right_bias_mps2 = 0.3;
  double safe_decel_mps2 = 4.0;
  NormalDist lane_change_duration_s;
  // Gipps (behaviour/gipps.hpp): reaction time and braking drawn per driver.
  NormalDist gipps_reaction_time_s;
  NormalDist gipps_max_decel_mps2;
  double gipps_leader_decel_estimate_mps2 = 3.0;
  // The Human Driver Model around the car-following model (behaviour/hdm.hpp): on when the
  // scenario gives the type a human_driver block. The reaction time is drawn per driver; the
  // other parameters are the type's.
  bool human_driver = false;
  NormalDist hdm_reaction_time_s;
  HdmParams hdm;
};

struct VehicleTypeConfig {
  std::string name;
  double length_m = 4.5;
  double width_m = 1.8;
  double max_decel_mps2 = 8.0;
  bool keep_right = false;
  DriverPopulation driver;
};

struct FlowConfig {
  double flow_veh_per_s = 0.0;
  // Cowan M3 headways of the arrivals (1 and 0: Poisson); see traffic/headways.hpp.
  double free_share = 1.0;
  double min_headway_s = 0.0;
  std::vector<double> type_shares;  // per vehicle type index, normalised to sum 1 (all 0 if no flow)
};

// The ego stand-in slows down (to a standstill by default) at its comfortable deceleration from
// at_s, holds at most speed_mps for duration_s once it got there, then drives on.
struct EgoStopConfig {
  double at_s = 0.0;
  double duration_s = 0.0;
  double speed_mps = 0.0;
};

struct EgoDriverConfig {
  bool use_speed_profile = false;
  double desired_speed_mps = 110.0 / 3.6;
  double time_gap_s = 1.5;
  double max_accel_mps2 = 1.0;
  double comfort_decel_mps2 = 1.5;
  double min_gap_m = 2.0;
  bool lane_changes = true;
  double politeness = 0.2;
  double coolness = 0.0;  // the ACC model's c (behaviour/cah.hpp); 0 = plain IDM
  std::vector<std::pair<double, double>> profile;  // (s_m, speed_mps), increasing s
  std::vector<EgoStopConfig> stops;                // increasing at_s
};

struct EgoConfig {
  double start_s_m = 1500.0;
  int lane = 0;
  double start_speed_mps = -1.0;  // < 0: the driver's desired speed at the start
  double length_m = 4.6;
  double width_m = 1.8;
  EgoDriverConfig driver;
  bool transparent = false;  // the traffic does not see it, it does not see the traffic (a probe)
};

// A role of a play: the vehicle it needs and where it must be, relative to the ego, at the
// handover (when the ego passes trigger point 2).
struct PlayRoleConfig {
  std::string name;
  int type_index = -1;                        // index into vehicle_types; -1: any type
  Direction direction = Direction::kForward;  // kBackward: an oncoming vehicle (two-way roads)
  // Forward roles: lane relative to the ego's lane at the handover (+1 = one to the left).
  // Oncoming roles: lane of the oncoming direction (0 = its rightmost).
  int lane_offset = 0;
  double ahead_m = 0.0;           // centre to centre along the ego's direction, > 0 ahead of it
  bool absolute_speed = false;    // speed_mps is absolute, else added to the ego's speed
  double speed_mps = 0.0;
  double position_tolerance_m = 10.0;
  double speed_tolerance_mps = 2.5;
};

// The speed a play asks for (a role's start speed, a speed action) with the ego at
// `ego_speed_mps`: `speed_mps` itself where it is absolute, else added to the ego's; never below
// standing.
inline double play_speed_mps(bool absolute_speed, double speed_mps, double ego_speed_mps) {
  const double v = absolute_speed ? speed_mps : ego_speed_mps + speed_mps;
  return v > 0.0 ? v : 0.0;
}

enum class PlayActionKind : std::uint8_t { kSpeed = 0, kLaneChange = 1, kIndicator = 2 };

// A scripted action of one role once the play runs. The actions of a role run in the order they
// are listed; each starts when the previous one of its role has started and its own conditions
// hold (all that are set).
struct PlayActionConfig {
  int role = 0;                   // index into roles
  double at_s = 0.0;              // not before this long after the handover
  double when_gap_below_m = -1;   // and only once |centre distance to the ego| < this (< 0: no)
  double when_ttc_below_s = -1;   // and only once the ego's time to collision with it < this (< 0: no)
  PlayActionKind kind = PlayActionKind::kSpeed;
  // kSpeed (a stop is speed 0): target speed, absolute or relative to the ego's speed when the
  // action starts, reached at rate_mps2 (acceleration or deceleration).
  bool absolute_speed = true;
  double speed_mps = 0.0;
  double rate_mps2 = 2.0;
  // kLaneChange: lanes relative to its current lane (+1 left); forced (no safety test) unless
  // `polite`; duration 0: the driver's own.
  int lane_offset = 0;
  bool polite = false;
  double duration_s = 0.0;
  // kIndicator: 0 off, 1 left, 2 right.
  std::uint8_t indicator = 0;
};

// A stretch that must hold no vehicle but the actors at the handover, relative to the ego (centre
// distances along its direction) in the lane `lane_offset` from the ego's.
struct PlayClearZoneConfig {
  int lane_offset = 0;
  double from_m = 0.0;
  double to_m = 0.0;
};

struct PlayConfig {
  std::uint32_t id = 0;
  std::string name;
  double trigger1_s_m = 0.0;  // the ego passes it: start preparing
  double trigger2_s_m = 0.0;  // the ego passes it: hand over to control, the script starts
  std::vector<PlayRoleConfig> roles;
  std::vector<PlayActionConfig> actions;
  std::vector<PlayClearZoneConfig> clear;
  double end_after_s = 30.0;       // the play ends this long after the handover
  double end_ego_beyond_s_m = -1;  // or once the ego passes this road position (< 0: no)
  double release_s = 5.0;          // the actors return to everyday driving over this time
  double handover_wait_s = 6.0;    // beyond trigger point 2, wait at most this long for the start condition
};

// How the director prepares plays (scenario `director`).
struct DirectorConfig {
  double accel_memory_s = 5.0;          // start-time estimate: how long the ego's acceleration lasts
  double max_speed_offset_mps = 8.0;    // transport: at most this far from the speed at the start
  double min_speed_mps = 5.0;           // transport: never slower (except a role's own start speed)
  double transport_rate_mps2 = 0.7;     // transport: speed changes are planned at this rate
  double max_jerk_mps3 = 2.0;           // actors' acceleration rises no faster than this
  double lane_change_cost_mps = 2.0;    // casting: cost of each lane change, as a speed change
  double hidden_margin_m = 50.0;        // created vehicles: at least this far beyond the inner region
  double beside_wait_ahead_m = 50.0;    // transport: a role beside the ego waits this far ahead of its start
  double beside_approach_s = 25.0;      // transport: ... until this long before the start
  double oncoming_gap_m = 800.0;        // one lane per direction: oncoming vehicles out of sight are
                                        // taken off over the ego's first metres of preparation (0: never)
};

struct ScenarioConfig {
  std::string name;
  double step_s = 0.1;
  double duration_s = 300.0;
  std::uint64_t seed = 1;
  RoadConfig road;
  WindowConfig window;
  std::vector<VehicleTypeConfig> vehicle_types;
  FlowConfig forward;
  FlowConfig backward;
  double demand_regulation_gain = 4.0;  // see scenario.proto, Demand.regulation_gain
  bool demand_regulation_whole_window = false;  // Demand.regulation_counts: the whole window, else the outer regions
  EgoConfig ego;
  std::vector<PlayConfig> plays;
  DirectorConfig director;
  SpeedAdaptationParams speed_adaptation;
  OvertakingParams overtaking;

  const FlowConfig& flow(Direction d) const { return d == Direction::kForward ? forward : backward; }
  std::uint64_t steps() const;  // number of steps in duration_s
};

}  // namespace entourage
