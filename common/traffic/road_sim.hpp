#pragma once
// A whole road simulated microscopically, without a moving window: the micro region's driving
// (car following with speed adaptation and the HDM, MOBIL and mandatory lane changes, overtaking
// in the oncoming lane) on a road with sources at its ends. Vehicles of a direction's demand
// enter at its upstream end (Poisson arrivals at the demanded flow, types and basic desired speeds
// from the demand; a queue forms when the entrance is full) and leave at the other end; detectors
// at fixed positions record every crossing.
//
// Used to learn the stationary stream the model produces at a demand (generator calibration), for
// fundamental diagrams, and for benchmarks against other simulators (entourage-roadsim). Pure: no
// clock, threads or I/O; all draws from its seeded stream.

#include <array>
#include <cstdint>
#include <deque>

#include "traffic/headways.hpp"
#include <limits>
#include <memory>
#include <vector>

#include "core/random.hpp"
#include "scenario/config.hpp"
#include "traffic/driving.hpp"
#include "traffic/fleet.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/stream.hpp"

namespace entourage {

struct Crossing {
  double time_s = 0.0;
  Direction direction = Direction::kForward;
  int lane = 0;
  double speed_mps = 0.0;
  double desired_speed_mps = 0.0;
  std::uint8_t type_index = 0;
  VehicleId id = 0;
  double headway_s = std::numeric_limits<double>::infinity();  // to the previous crossing in the lane
};

struct RoadSimConfig {
  // The road: the scenario's own (its length, curves, speed zones, restrictions and closures) or,
  // by default, a straight road of length_m with the scenario's lanes, limit and kind: the
  // reference conditions the demand's desired speeds are stated for.
  bool scenario_road = false;
  double length_m = 8000.0;
  std::vector<double> detectors_m;  // positions along s
  bool forward = true;   // simulate the forward demand (entering at s = 0)
  bool backward = false; // simulate the backward demand (entering at s = length)
  DrivingRules rules;
};

// Counts for reports.
struct RoadSimCounters {
  std::uint64_t entered = 0;
  std::uint64_t left = 0;
  std::uint64_t lane_changes = 0;
  std::uint64_t overtakings_started = 0;
  std::uint64_t overtakings_aborted = 0;
  std::uint64_t emergency_decisions = 0;
  // Trips from entrance to exit: their number and the sum of their mean speeds (road length over
  // travel time), for a trip speed comparable with other simulators' statistics.
  std::uint64_t trips = 0;
  double trip_speed_sum_mps = 0.0;
  double mean_trip_speed_mps() const { return trips > 0 ? trip_speed_sum_mps / static_cast<double>(trips) : 0.0; }
};

class RoadSim {
 public:
  RoadSim(const ScenarioConfig& scenario, RoadSimConfig config, std::uint64_t seed);
  // The demand of one direction only, on the reference road (generator calibration). On a road
  // with oncoming traffic the opposite demand is simulated too, so that overtakings meet it.
  RoadSim(const ScenarioConfig& scenario, Direction demand_of, RoadSimConfig config, std::uint64_t seed);

  void step();

  double time_s() const { return static_cast<double>(steps_) * scenario_.step_s; }
  double length_m() const { return scenario_.road.length_m; }
  std::size_t vehicles() const { return fleet_.size(); }
  std::uint64_t vehicle_updates() const { return updates_; }
  std::size_t queued(Direction d) const { return source(d).queue.size(); }
  std::size_t queued() const { return queued(Direction::kForward) + queued(Direction::kBackward); }
  const std::vector<Crossing>& crossings(std::size_t detector) const { return crossings_[detector]; }
  const Fleet& fleet() const { return fleet_; }
  // Gives a vehicle on the road another driver (a bench puts drivers like the ego stand-in into
  // the stream this way). False if the vehicle is not on the road.
  bool redrive(VehicleId id, const DriverParams& driver);
  const DrivingEnvironment& environment() const { return env_; }
  // The vehicles that left the road's end in the last step, as they were when they left.
  const std::vector<Vehicle>& exits() const { return exits_; }
  const StreamModel& demand(Direction d) const { return *source(d).stream; }
  const StreamModel& demand() const { return demand(Direction::kForward); }
  const RoadSimCounters& counters() const { return counters_; }
  const ScenarioConfig& scenario() const { return scenario_; }

 private:
  struct Source {
    bool active = false;
    std::unique_ptr<StreamModel> stream;
    std::deque<SpeedDraw> queue;
    CompositeHeadways headways;  // Poisson: arrivals by integrated rate; else by drawn headways
    double accumulated = 0.0;    // integrated rate (Poisson) or time (composite) since the last arrival
    double next_arrival = 1.0;
  };
  Source& source(Direction d) { return sources_[dir_index(d)]; }
  const Source& source(Direction d) const { return sources_[dir_index(d)]; }

  void arrive();
  void enter(Direction d);
  void perceive();
  void move();
  void detect(const std::vector<double>& before);
  void remove_finished();

  ScenarioConfig scenario_;
  RoadSimConfig config_;
  DrivingEnvironment env_;
  Random rng_;
  std::uint64_t seed_;
  std::array<Source, 2> sources_;
  Fleet fleet_;
  LaneIndex index_;
  VehicleId next_id_ = 1;
  std::uint64_t steps_ = 0;
  std::uint64_t updates_ = 0;
  RoadSimCounters counters_;
  std::vector<Decision> decisions_;
  std::vector<std::vector<Crossing>> crossings_;
  std::vector<std::vector<double>> last_crossing_time_;  // per detector, per (direction, lane)
  std::vector<Vehicle> exits_;
  std::vector<double> entry_time_s_;
  std::vector<double> positions_before_;  // s of each vehicle before the step's movement  // by vehicle id (ids are consecutive from 1)
};

// The scenario as the road simulation uses it: for the reference road, the road replaced by a
// straight one of `length_m` (lanes, limit and kind kept; curves, zones, restrictions and closures
// dropped).
ScenarioConfig road_sim_scenario(const ScenarioConfig& scenario, const RoadSimConfig& config);

// Whether the stretch [from_m, to_m] of `road` is like the reference road the demand's stream is
// observed on (road_sim_scenario without scenario_road): straight, at the road's own limit, with
// overtaking allowed and every lane open. The moving-observer relations of that stream hold for an
// observer whose surroundings are such a stretch; a curve or a speed zone slows the stream and the
// observer together (a probe at 85 km/h on the rural road, its prediction counted through both
// 70 km/h curves, was passed 0.83 times as often as predicted, 1.5 times on the same road straight;
// stop 40).
bool like_reference_road(const RoadConfig& road, double from_m, double to_m);

// Whether the whole window around an ego at `ego_s_m` is on such a stretch: the steps at which its
// catch-ups count against the prediction (recording/summary.hpp, the catch-up benches).
bool window_like_reference_road(const ScenarioConfig& scenario, double ego_s_m);

}  // namespace entourage
