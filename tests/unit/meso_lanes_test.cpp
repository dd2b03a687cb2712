// Meso's lane rule (services/meso/core/meso_lanes.hpp): a blocked vehicle moves to the next lane
// only where the follower there keeps its safe gap and, closing in, would not brake harder than
// MOBIL's safe deceleration.
#include <gtest/gtest.h>

#include "meso/core/meso_lanes.hpp"
#include "traffic/fleet.hpp"
#include "traffic/lane_index.hpp"

namespace entourage::meso {
namespace {

Vehicle car(VehicleId id, int lane, double s_m, double speed_mps, double desired_mps) {
  Vehicle c;
  c.id = id;
  c.lane = lane;
  c.s_m = s_m;
  c.speed_mps = speed_mps;
  c.length_m = 4.5;
  c.driver.car_following.idm.desired_speed_mps = desired_mps;
  c.driver.car_following.idm.time_gap_s = 1.2;
  c.driver.lane_change = LaneChangeModel::kMobil;
  c.lane_change.from_lane = c.lane_change.to_lane = lane;
  c.lane_change.since_last_change_s = 60.0;
  return c;
}

class MesoLaneRule : public ::testing::Test {
 protected:
  LaneIndex index{2, 0};
  Fleet fleet;
  void drive(const Vehicle& v) {
    Handoff h;
    h.vehicle = v;
    fleet.adopt(h, 0, 0.1);
  }
  std::optional<int> lane_for(VehicleId id) {
    build_index(index, fleet, {}, nullptr);
    const Vehicle& v = *fleet.find(id);
    const Occupant* leader = index.leader(v.direction, v.lane, v.progress_m(), v.id);
    const double gap = leader == nullptr ? -1.0 : gap_between(*leader, v.progress_m(), v.length_m);
    return choose_lane(v, index, gap, LaneRules{});
  }
};

// Blocked 20 m behind a car 8 m/s slower, with the left lane free ahead: it moves over when the
// follower there is at its own speed 50 m back (gap above s0 + v T = 2 + 25 x 1.2 = 32 m) ...
TEST_F(MesoLaneRule, ABlockedVehiclePassesWhenTheFollowerThereKeepsItsGap) {
  drive(car(1, 0, 1000.0, 25.0, 33.0));
  drive(car(2, 0, 1024.5, 17.0, 17.0));
  drive(car(3, 1, 1000.0 - 4.5 - 50.0, 25.0, 33.0));
  EXPECT_EQ(lane_for(1), 1);
}

// ... but not in front of one closing in 9 m/s faster at the same distance: the gap exceeds the
// safe gap at the follower's speed (2 + 34 x 1.2 = 43 m), yet that follower's own model would brake
// far beyond b_safe = 4 m/s^2 (a car braked at 9 m/s^2 behind such a change, freeway seed 1).
TEST_F(MesoLaneRule, NorInFrontOfAFollowerClosingInTooFastForItsOwnBrakes) {
  drive(car(1, 0, 1000.0, 25.0, 33.0));
  drive(car(2, 0, 1024.5, 17.0, 17.0));
  drive(car(3, 1, 1000.0 - 4.5 - 50.0, 34.0, 36.0));
  EXPECT_EQ(lane_for(1), std::nullopt);
}

}  // namespace
}  // namespace entourage::meso
