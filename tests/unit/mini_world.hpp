#pragma once
// A few hand-built vehicles stepped with the same phases as the micro region (index, decide all,
// commit all), checking after every step that no two overlap: the small world the driving tests
// put drivers in.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core_test_util.hpp"
#include "traffic/driving.hpp"
#include "traffic/world.hpp"

namespace entourage::testing {

inline Vehicle car(VehicleId id, Direction dir, int lane, double s, double v, double v0,
                   LaneChangeModel lc = LaneChangeModel::kMobil) {
  Vehicle c;
  c.id = id;
  c.direction = dir;
  c.lane = lane;
  c.s_m = s;
  c.speed_mps = v;
  c.length_m = 4.5;
  c.driver.car_following.idm = {v0, 1.2, 1.5, 2.0, 2.0, 4.0};
  c.driver.lane_change = lc;
  c.driver.max_decel_mps2 = 9.0;
  c.driver.rng_state = 1000 + id;
  c.lane_change.from_lane = c.lane_change.to_lane = lane;
  c.lane_change.since_last_change_s = 100.0;
  return c;
}

inline Vehicle truck(VehicleId id, Direction dir, double s, double v) {
  Vehicle t = car(id, dir, 0, s, v, v, LaneChangeModel::kNone);
  t.length_m = 16.5;
  t.driver.car_following.idm.max_accel_mps2 = 0.5;
  return t;
}

// A few vehicles stepped with the same phases as the micro region: index, decide all, commit all.
struct MiniWorld {
  explicit MiniWorld(const ScenarioConfig& sc)
      : env(sc), index(sc.road.lanes_forward, sc.road.lanes_backward) {}

  void build_index() {
    index.clear();
    for (const Vehicle& v : vehicles) {
      add_to_index(index, v.direction, v.lane, v.target_lane(), v.id, v.progress_m(), v.speed_mps, v.accel_mps2,
                   v.length_m);
    }
    index.sort();
  }
  std::vector<Decision> decide_all() {
    build_index();
    std::vector<Decision> d;
    for (const Vehicle& v : vehicles) d.push_back(decide(v, index, env));
    return d;
  }
  void step() {
    const std::vector<Decision> d = decide_all();
    for (std::size_t i = 0; i < vehicles.size(); ++i) commit(vehicles[i], d[i], env.dt_s());
    check_no_overlap();
  }
  Vehicle& get(VehicleId id) {
    for (Vehicle& v : vehicles) {
      if (v.id == id) return v;
    }
    throw std::runtime_error("no such vehicle");
  }
  // Physical lane numbered from the forward direction's right edge, for both directions.
  int physical(const Vehicle& v, int lane) const {
    return v.direction == Direction::kForward ? lane : env.lanes(Direction::kForward) + env.lanes(Direction::kBackward) - 1 - lane;
  }
  bool shares_lane(const Vehicle& a, const Vehicle& b) const {
    for (int la : {a.lane, a.target_lane()}) {
      for (int lb : {b.lane, b.target_lane()}) {
        if (physical(a, la) == physical(b, lb)) return true;
      }
    }
    return false;
  }
  void check_no_overlap() {
    for (std::size_t i = 0; i < vehicles.size(); ++i) {
      for (std::size_t j = i + 1; j < vehicles.size(); ++j) {
        const Vehicle& a = vehicles[i];
        const Vehicle& b = vehicles[j];
        if (!shares_lane(a, b)) continue;
        const double apart = std::abs(a.s_m - b.s_m) - 0.5 * (a.length_m + b.length_m);
        min_clearance_m = std::min(min_clearance_m, apart);
        EXPECT_GT(apart, 0.0) << "vehicles " << a.id << " and " << b.id << " overlap at t = " << t();
      }
    }
    ++steps;
  }
  double t() const { return steps * env.dt_s(); }

  DrivingEnvironment env;
  LaneIndex index;
  std::vector<Vehicle> vehicles;
  double min_clearance_m = std::numeric_limits<double>::infinity();
  int steps = 0;
};

}  // namespace entourage::testing
