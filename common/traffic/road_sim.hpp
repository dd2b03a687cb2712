#pragma once
// A whole straight road simulated microscopically, without a moving window: vehicles of one
// direction's demand enter at s = 0 (Poisson arrivals at the demanded flow, desired speeds and
// types from the demand) and leave at the end; detectors at fixed positions record every
// crossing. The same driving functions as the inner region (IDM, MOBIL, lane changes over time).
//
// Used to learn the stationary stream the model produces at a demand (generator calibration),
// for fundamental diagrams, and for benchmarks against other simulators. Pure: no clock, threads
// or I/O; all draws from its seeded stream.

#include <cstdint>
#include <deque>
#include <limits>
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
  int lane = 0;
  double speed_mps = 0.0;
  double desired_speed_mps = 0.0;
  std::uint8_t type_index = 0;
  VehicleId id = 0;
  double headway_s = std::numeric_limits<double>::infinity();  // to the previous crossing in the lane
};

struct RoadSimConfig {
  double length_m = 8000.0;
  std::vector<double> detectors_m;
  DrivingRules rules;
};

class RoadSim {
 public:
  // Simulates the demand of `demand_of` (its flow, mix and drivers) on a road with that
  // direction's lanes, in the forward direction.
  RoadSim(const ScenarioConfig& scenario, Direction demand_of, RoadSimConfig config, std::uint64_t seed);

  void step();

  double time_s() const { return static_cast<double>(steps_) * scenario_.step_s; }
  std::size_t vehicles() const { return fleet_.size(); }
  std::uint64_t vehicle_updates() const { return updates_; }
  std::size_t queued() const { return queue_.size(); }
  const std::vector<Crossing>& crossings(std::size_t detector) const { return crossings_[detector]; }
  const Fleet& fleet() const { return fleet_; }
  // The vehicles that left the road's end in the last step, as they were when they left.
  const std::vector<Vehicle>& exits() const { return exits_; }
  const StreamModel& demand() const { return stream_; }

 private:
  void arrive();
  void enter();
  void perceive();
  void move();
  void detect(const std::vector<double>& before);
  void remove_finished();

  ScenarioConfig scenario_;
  RoadSimConfig config_;
  StreamModel stream_;
  Random rng_;
  std::uint64_t seed_;
  Fleet fleet_;
  LaneIndex index_;
  std::deque<SpeedDraw> queue_;
  double accumulated_ = 0.0;
  double next_arrival_ = 1.0;
  VehicleId next_id_ = 1;
  std::uint64_t steps_ = 0;
  std::uint64_t updates_ = 0;
  std::vector<std::vector<Crossing>> crossings_;
  std::vector<std::vector<double>> last_crossing_time_;  // per detector, per lane
  std::vector<Vehicle> exits_;
};

}  // namespace entourage
