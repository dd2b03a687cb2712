#pragma once
// One run of a scenario's first play with every core in one process (window_cores.hpp), in
// lockstep, and what it measured: the outcome, the errors at the handover, how the actors drove
// while they were moved into place against the autonomous vehicles around them, where vehicles
// were created, and whether any vehicle overlapped another. Used by entourage-bench-director and
// by the tests that assert the shipped plays.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "director/core/stage.hpp"
#include "window_cores.hpp"

namespace entourage::bench {

// How the ego stand-in drives in a run: the scenario's driver at a varied desired speed, one who
// brakes (to 60 % of its speed for 6 s) in the middle of the preparation, or one who changes lane
// (or overtakes) readily.
enum class EgoVariant : std::uint8_t { kSteady = 0, kBrakes = 1, kChangesLane = 2 };
const char* to_string(EgoVariant v);

// The scenario as run `index` of a series drives it: variant index % 3, desired speed spread
// +-15 km/h around the scenario's by a draw from `seed`.
ScenarioConfig vary_ego(ScenarioConfig sc, int index, std::uint64_t seed, EgoVariant* variant);

// A run measures the scenario's first play (the ego's braking, the figures and the end of the run
// follow it); the others are prepared and run as well. Puts the play named `name` first, the
// others after it in their order, and returns whether the scenario has it.
bool measure_play(ScenarioConfig& sc, const std::string& name);

struct MotionExtremes {
  double max_accel_mps2 = 0.0;
  double max_decel_mps2 = 0.0;  // positive
  double max_jerk_mps3 = 0.0;   // |da/dt|
  std::uint64_t vehicle_steps = 0;
  void add(double accel_mps2, double jerk_mps3) {
    max_accel_mps2 = std::max(max_accel_mps2, accel_mps2);
    max_decel_mps2 = std::max(max_decel_mps2, -accel_mps2);
    max_jerk_mps3 = std::max(max_jerk_mps3, std::abs(jerk_mps3));
    ++vehicle_steps;
  }
};

struct SignalsCalledOff {
  int count = 0;
  double vehicle_s = 0.0;  // time the vehicles of this kind spent in the inner region
  // How long each indicator that went off in view had been on (changes made, with their lateral
  // movement, and changes called off): a request held too long shows as a driver signalling on.
  std::vector<double> signal_s;
  void add(const SignalsCalledOff& o) {
    count += o.count;
    vehicle_s += o.vehicle_s;
    signal_s.insert(signal_s.end(), o.signal_s.begin(), o.signal_s.end());
  }
  double per_vehicle_hour() const { return vehicle_s > 0.0 ? 3600.0 * count / vehicle_s : 0.0; }
};

// The vehicles the ego passed on the right: it overtook them from a lane to the right of theirs,
// neither changing lanes meanwhile (lanes count from the right). Freeway drivers keep right and
// pass on the left; a driver who passes a column of cars in the passing lane on the right sees
// traffic that does not behave like traffic (the slow column of cleared vehicles of stop 33).
struct RightPasses {
  int commanded = 0;   // under a director's command at the time
  int autonomous = 0;
  int total() const { return commanded + autonomous; }
  void add(const RightPasses& o) {
    commanded += o.commanded;
    autonomous += o.autonomous;
  }
};
class RightPassCounter {
 public:
  // One step: the ego and the world as published for the same step; each pass is printed to
  // `trace` if not null.
  void observe(const EgoObservation& ego, const std::vector<ObservedVehicle>& world, RightPasses& out,
               std::FILE* trace = nullptr);

 private:
  std::map<VehicleId, double> ahead_m_;  // last step's lead over the ego of each vehicle left of it
};

// Lane changes made in the inner region while a play is prepared, by vehicles under a director's
// transport command and by autonomous ones: a vehicle counts one when its lane differs from the
// one it had the step before as the same kind (a change counts as its lateral movement ends).
// Per run, the most one vehicle made: a vehicle sent back and forth between two lanes by two of
// the director's rules shows there (cut-in seed 145, stop 66: seven changes in 47 s).
inline constexpr int kManyLaneChanges = 3;
struct LaneChangesMade {
  int count = 0;
  double vehicle_s = 0.0;  // time the vehicles of this kind spent in the inner region
  int most_by_one = 0;     // by one vehicle in a run (over several runs: the largest)
  int runs_with_many = 0;  // runs in which one vehicle made kManyLaneChanges or more
  void add(const LaneChangesMade& o) {
    count += o.count;
    vehicle_s += o.vehicle_s;
    most_by_one = std::max(most_by_one, o.most_by_one);
    runs_with_many += o.runs_with_many;
  }
  double per_vehicle_hour() const { return vehicle_s > 0.0 ? 3600.0 * count / vehicle_s : 0.0; }
};
class LaneChangeCounter {
 public:
  // One step of a vehicle that is to be counted (in the inner region while preparing; a vehicle
  // controlled by a script or being released is not, and forgotten).
  void observe(const ObservedVehicle& v, double dt_s);
  // A vehicle not counted at this step: its next change is not one made in view.
  void forget(VehicleId id) { last_.erase(id); }
  // The run's figures for each kind.
  LaneChangesMade commanded() const { return made(made_commanded_, commanded_s_); }
  LaneChangesMade autonomous() const { return made(made_autonomous_, autonomous_s_); }

 private:
  static LaneChangesMade made(const std::map<VehicleId, int>& by_vehicle, double vehicle_s);
  std::map<VehicleId, std::pair<int, ControlMode>> last_;  // lane and control at the last step counted
  std::map<VehicleId, int> made_commanded_;
  std::map<VehicleId, int> made_autonomous_;
  double commanded_s_ = 0.0;
  double autonomous_s_ = 0.0;
};

// Vehicles in view faster than any driver of their type wishes to drive (the scenario's highest
// desired speed of the type, `desired_speed_kph { max }`): a truck at 127 km/h where trucks wish
// 95 at most is not everyday traffic, whoever asked it to.
struct AboveTopSpeed {
  double vehicle_s = 0.0;       // time vehicles of this kind spent above it
  double max_excess_mps = 0.0;  // by how much at most
  int runs = 0;                 // over runs: runs in which any did
  void add_step(double excess_mps, double dt_s) {
    vehicle_s += dt_s;
    max_excess_mps = std::max(max_excess_mps, excess_mps);
  }
  void add(const AboveTopSpeed& o) {
    vehicle_s += o.vehicle_s;
    max_excess_mps = std::max(max_excess_mps, o.max_excess_mps);
    runs += o.vehicle_s > 0.0 ? 1 : 0;
  }
};

struct PlayRunResult {
  director::PlayPhase final_phase = director::PlayPhase::kWaiting;
  bool handed_over = false;
  std::string failure;               // the failed report's detail
  double position_error_m = 0.0;     // at the handover, the largest over the roles
  double speed_error_mps = 0.0;
  // The errors of the director's report in the step the ego passed trigger point 2 (the handover
  // itself, or what was still missing then; the position error's size); < 0 if none (nothing was
  // cast).
  double position_error_at_trigger2_m = -1.0;
  double speed_error_at_trigger2_mps = -1.0;
  // What the start condition lacked when the ego passed trigger point 2 ("role: ... ; vehicle ...
  // in a clear zone", as in a failure's detail; the director reports it at that step); empty if
  // it was met then or nothing was cast.
  std::string missing_at_trigger2;
  double estimate_error_s = 0.0;     // first estimate (trigger point 1) - actual handover time
  double trigger1_time_s = -1.0;     // when the ego passed trigger point 1 (< 0: never)
  double trigger2_time_s = -1.0;     // and trigger point 2
  // The ego's time from trigger point 1 to 2 beyond that of the same run without the director
  // (trigger_times_undirected; filled by the caller): how long the director held the ego up.
  double held_up_s = 0.0;
  double handover_wait_s = 0.0;      // handed over this long after the ego passed trigger point 2
  double handover_beyond_m = 0.0;    // and the ego this far beyond it
  MotionExtremes actors;             // the roles' actors while transported, in the inner region (micro)
  MotionExtremes cleared;            // the other vehicles under a transport command (asked to leave a
                                     // zone, make way, let one in or keep their lane), same steps
  MotionExtremes autonomous;         // the autonomous vehicles of the inner region, same steps
  // The longest a vehicle drove beside the ego without a break while the play was prepared (in a
  // neighbouring lane of its direction, its centre within kBesideEgo_m of the ego's): one under a
  // director's command, and an autonomous one. A driver notices a car that paces them.
  double actor_beside_ego_s = 0.0;
  double autonomous_beside_ego_s = 0.0;
  // How long the play's actors drove held up while it was prepared: more than kHeldUpBelow_mps
  // below the desired speed the director last gave them, within kHeldUpWithin_s (at their speed)
  // of a leader in their lane, the ego included; and of that, how long that leader was itself
  // under a director's command (stop 65: the cutters of most failed cut-ins spent 10 s or more so,
  // mostly behind vehicles the director was moving).
  double actor_held_up_s = 0.0;
  double actor_held_up_by_commanded_s = 0.0;
  // The vehicles the ego passed on the right from trigger point 1 to 2 (RightPasses), and in the
  // same run without the director (filled by the caller).
  RightPasses passed_on_right;
  RightPasses passed_on_right_undirected;
  // The mean speed of the ego's direction's vehicles in the inner region while the ego drove from
  // trigger point 1 to 2 (< 0: it did not): against the same run without the director, how much
  // the director slowed the traffic around the driver.
  double traffic_speed_mps = -1.0;
  double traffic_speed_undirected_mps = -1.0;  // filled by the caller (trigger_times_undirected)
  double traffic_slowed_to() const {           // with / without the director (< 0: unknown)
    return traffic_speed_mps > 0.0 && traffic_speed_undirected_mps > 0.0 ? traffic_speed_mps / traffic_speed_undirected_mps
                                                                        : -1.0;
  }
  // Signals a driver sees and that come to nothing: a vehicle in the inner region whose indicator
  // went on and off again in the same lane while the play was prepared (a lane change called
  // off), under a director's command and autonomous, with the time each kind spent there.
  SignalsCalledOff called_off_commanded;
  // Above their type's top desired speed in the inner region while the play was prepared: under a
  // director's transport command (actors and cleared vehicles), and autonomous.
  AboveTopSpeed above_top_commanded;
  AboveTopSpeed above_top_autonomous;
  SignalsCalledOff called_off_autonomous;
  LaneChangesMade lane_changes_commanded;
  LaneChangesMade lane_changes_autonomous;
  // The ego's lane changes begun between trigger points 1 and 2 (on a two-lane road, its passes in
  // the oncoming lane), and whether it passed trigger point 2 in a lane beside which the play is
  // staged mirrored (director/core/stage.hpp, staged_beside: a cut-in's cutter then comes from the
  // right). Each change of lane restages a play whose roles or zones lie in other lanes.
  int ego_lane_changes = 0;
  bool mirrored_at_trigger2 = false;
  int created = 0;
  int created_in_view = 0;           // born inside the inner region: must be 0
  int taken_off = 0;                 // withdrawn by the director (a gap in the oncoming traffic)
  int taken_off_for_room = 0;        // of them of the ego's direction (room for a creation)
  int taken_off_in_view = 0;         // of them inside the inner region: must be 0
  int overlaps_with_actor = 0;       // vehicle pairs overlapping where one is an actor
  int overlaps_other = 0;            // any other overlapping pair (autonomous traffic)
  int ego_contacts_with_actor = 0;   // the ego overlapping an actor (the ego may crash)
  // Two commands or more to one vehicle in one step of the director's output (one phase undoing
  // another's command; must be 0).
  int commanded_twice_in_a_step = 0;
  Step steps = 0;
};

inline constexpr double kBesideEgo_m = 15.0;
// An actor held up (PlayRunResult::actor_held_up_s): this much below its desired speed, this close
// (in seconds at its speed, bumper to bumper) behind its leader.
inline constexpr double kHeldUpBelow_mps = 2.0;
inline constexpr double kHeldUpWithin_s = 2.0;

// The nearest vehicle ahead of `v` in its lane, the ego included: the gap to it (bumper to bumper)
// and whether it is under a director's command; nullopt: nobody ahead.
struct LeaderGap {
  double gap_m = 0.0;
  bool commanded = false;
};
std::optional<LeaderGap> leader_gap(const ObservedVehicle& v, const std::vector<ObservedVehicle>& world,
                                    const EgoObservation& ego);

// Whether `play`, staged beside the lane `ego` is in or moving to, is mirrored (the director's
// own decision, stage.hpp, mirrored_beside).
bool staged_mirrored(const PlayConfig& play, const EgoObservation& ego, const director::Lanes& lanes);

// `trace`: if not null, every play report of the run is printed there, one line each.
// `trace`: every play report; `traffic`: every 2 s from trigger point 1 on, the vehicles around the
// ego ("id@ahead/speed/Llane", `<` oncoming, then T transported, C controlled, R releasing).
PlayRunResult run_play(const ScenarioConfig& sc, std::uint64_t seed, std::FILE* trace = nullptr,
                       std::FILE* traffic = nullptr);

// The same run without the director (the scenario's plays removed): when the ego passes the first
// play's trigger points 1 and 2 in traffic that nobody stages (< 0: never). Against
// PlayRunResult's times, how much the director held the ego up.
struct TriggerTimes {
  double trigger1_s = -1.0;
  double trigger2_s = -1.0;
  double traffic_speed_mps = -1.0;  // as PlayRunResult's
  RightPasses passed_on_right;      // trigger point 1 to 2
};
TriggerTimes trigger_times_undirected(const ScenarioConfig& sc, std::uint64_t seed);

// The Wilson score interval of a success rate (Wilson 1927): `successes` of `runs` trials, at the
// normal quantile `z` (1.96: 95 %). Unlike p +- z sqrt(p (1 - p) / n) it stays within [0, 1] and
// does not shrink to nothing at 0 or n successes, which 50 runs of a play that mostly succeeds
// need: 45 of 50 is 79-96 %, not 90 +- 8 %.
struct RateInterval {
  double low = 0.0;
  double high = 1.0;
};
RateInterval wilson_interval(int successes, int runs, double z = 1.96);

}  // namespace entourage::bench
