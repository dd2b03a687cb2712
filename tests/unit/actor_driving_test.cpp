// The event director's control over a driver's own model (traffic/actor_driving.hpp): a
// transported vehicle drives at the director's speed towards its lane and makes no lane change of
// its own; a controlled one follows the script without driving into the vehicle ahead, cuts in
// where the lane is physically free, and shows the script's indicator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core_test_util.hpp"
#include "mini_world.hpp"

namespace entourage {
namespace {

using testing::car;
using testing::MiniWorld;
using testing::truck;

ActorControl transported(double speed_mps, int lane = -1) {
  ActorControl c;
  c.mode = ControlMode::kTransported;
  c.play_id = 1;
  c.speed_mps = speed_mps;
  c.lane = lane;
  return c;
}

ActorControl controlled(double speed_mps, double rate_mps2) {
  ActorControl c;
  c.mode = ControlMode::kControlled;
  c.play_id = 1;
  c.speed_mps = speed_mps;
  c.accel_mps2 = c.decel_mps2 = rate_mps2;
  return c;
}

TEST(ActorDriving, ATransportedVehicleDrivesAtTheDirectorsSpeedWithBoundedJerk) {
  MiniWorld w(testing::road_scenario(2, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 20.0, 33.0);
  v.control = transported(26.0);
  w.vehicles.push_back(v);
  double prev_a = 0.0;
  double max_rise = 0.0;
  for (int i = 0; i < 900; ++i) {
    w.step();
    max_rise = std::max(max_rise, (w.get(1).accel_mps2 - prev_a) / w.env.dt_s());
    prev_a = w.get(1).accel_mps2;
  }
  EXPECT_NEAR(w.get(1).speed_mps, 26.0, 0.3);  // not its own 33
  EXPECT_LE(max_rise, v.control.max_jerk_mps3 + 1e-9);
  EXPECT_EQ(w.get(1).lane, 0);  // no lane change of its own
}

TEST(ActorDriving, ATransportedVehicleFarAboveTheDirectorsSpeedEasesDownAtItsComfortableDeceleration) {
  // Told to drive 10 m/s below its speed (a follower asked to let a car in): the model's free-road
  // term alone would brake at a [1 - (30/20)^4] = -6 m/s^2 and more; a driver eases down at b.
  MiniWorld w(testing::road_scenario(2, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 30.0, 33.0);
  v.control = transported(20.0);
  w.vehicles.push_back(v);
  const double b = v.driver.car_following.idm.comfort_decel_mps2;
  double hardest = 0.0;
  for (int i = 0; i < 300; ++i) {
    w.step();
    hardest = std::min(hardest, w.get(1).accel_mps2);
  }
  EXPECT_GE(hardest, -b - 1e-9);
  EXPECT_LT(hardest, -0.5 * b);               // it does slow down, not merely coast
  EXPECT_NEAR(w.get(1).speed_mps, 20.0, 0.3);  // and arrives at the director's speed
}

TEST(ActorDriving, AVehicleEasingDownStillBrakesAsHardAsItsLeaderNeeds) {
  // Easing down towards the director's speed, a crawling truck 50 m ahead (closing at 20 m/s needs
  // some 4 m/s^2): car following, not the easing, sets the braking, and it stays behind the truck.
  MiniWorld w(testing::road_scenario(1, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 25.0, 33.0);
  v.control = transported(20.0);
  w.vehicles = {v, truck(2, Direction::kForward, 1060.0, 5.0)};
  double hardest = 0.0;
  for (int i = 0; i < 300; ++i) {
    w.step();
    hardest = std::min(hardest, w.get(1).accel_mps2);
  }
  EXPECT_LT(hardest, -v.driver.car_following.idm.comfort_decel_mps2);
  EXPECT_GT(w.min_clearance_m, 1.0);
  EXPECT_NEAR(w.get(1).speed_mps, 5.0, 0.5);
}

TEST(ActorDriving, ATransportedVehicleGoesToTheDirectorsLaneAndStaysThere) {
  MiniWorld w(testing::road_scenario(3, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 25.0, 25.0);
  v.control = transported(25.0, 2);
  w.vehicles.push_back(v);
  for (int i = 0; i < 400; ++i) w.step();
  EXPECT_EQ(w.get(1).lane, 2);
  EXPECT_FALSE(w.get(1).lane_change.active());
}

TEST(ActorDriving, AVehicleOnlyAskedForALaneKeepsItsOwnDesiredSpeed) {
  MiniWorld w(testing::road_scenario(2, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 20.0, 33.0);
  v.control = transported(kOwnDesiredSpeed_mps, 1);
  w.vehicles.push_back(v);
  for (int i = 0; i < 900; ++i) w.step();
  EXPECT_NEAR(w.get(1).speed_mps, 33.0, 0.3);
  EXPECT_EQ(w.get(1).lane, 1);
}

TEST(ActorDriving, AnAutonomousDriverWouldHaveChangedLaneWhereATransportedOneKeepsIt) {
  // Behind a slow truck with a free left lane: MOBIL changes lane, an actor keeps its part.
  for (const bool actor : {false, true}) {
    MiniWorld w(testing::road_scenario(2, 0));
    Vehicle v = car(1, Direction::kForward, 0, 1000.0, 25.0, 30.0);
    if (actor) v.control = transported(30.0);
    w.vehicles = {v, truck(2, Direction::kForward, 1060.0, 20.0)};
    bool changed = false;
    for (int i = 0; i < 300; ++i) {
      w.step();
      changed = changed || w.get(1).lane != 0 || w.get(1).lane_change.active();
    }
    EXPECT_EQ(changed, !actor) << (actor ? "actor" : "autonomous");
  }
}

TEST(ActorDriving, AControlledActorBrakesAtTheScriptsRateToAStandstill) {
  MiniWorld w(testing::road_scenario(2, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 30.0, 30.0);
  v.control = controlled(0.0, 6.0);
  w.vehicles.push_back(v);
  w.step();
  EXPECT_NEAR(w.get(1).accel_mps2, -6.0, 1e-9);
  for (int i = 0; i < 60; ++i) w.step();
  EXPECT_DOUBLE_EQ(w.get(1).speed_mps, 0.0);
  const double s_stopped = w.get(1).s_m;
  for (int i = 0; i < 50; ++i) w.step();
  EXPECT_DOUBLE_EQ(w.get(1).s_m, s_stopped);  // stays stopped: the script's speed is 0
}

TEST(ActorDriving, AControlledActorNeverDrivesIntoTheVehicleAhead) {
  // The script asks for 35 m/s; a slower vehicle 40 m ahead holds it back.
  MiniWorld w(testing::road_scenario(1, 0));
  Vehicle v = car(1, Direction::kForward, 0, 1000.0, 30.0, 30.0);
  v.control = controlled(35.0, 2.0);
  w.vehicles = {v, truck(2, Direction::kForward, 1040.0, 20.0)};
  for (int i = 0; i < 600; ++i) w.step();
  EXPECT_GT(w.min_clearance_m, 2.0);
  EXPECT_NEAR(w.get(1).speed_mps, 20.0, 0.5);
}

TEST(ActorDriving, AForcedLaneChangeStartsAtOnceUnlessTheTargetLaneIsPhysicallyOccupied) {
  MiniWorld w(testing::road_scenario(2, 0));
  Vehicle actor = car(1, Direction::kForward, 1, 1000.0, 25.0, 25.0);
  actor.control = controlled(25.0, 2.0);
  actor.control.lane = 0;
  actor.control.force_lane = true;
  actor.control.lane_change_duration_s = 2.0;
  // A car 8 m behind in the target lane (bumper gap 3.5 m): MOBIL would refuse, a cut-in goes.
  w.vehicles = {actor, car(2, Direction::kForward, 0, 992.0, 25.0, 25.0)};
  std::vector<Decision> d = w.decide_all();
  EXPECT_EQ(d[0].lane_change.phase, LaneChangePhase::kMoving);
  EXPECT_EQ(d[0].lane_change.to_lane, 0);
  EXPECT_DOUBLE_EQ(d[0].lane_change.duration_s, 2.0);
  // Beside it: no change.
  w.get(2).s_m = 1002.0;
  d = w.decide_all();
  EXPECT_EQ(d[0].lane_change.phase, LaneChangePhase::kNone);
}

TEST(ActorDriving, AControlledActorShowsTheScriptsIndicator) {
  Vehicle v = car(1, Direction::kForward, 1, 1000.0, 25.0, 25.0);
  EXPECT_EQ(v.indicator(), Indicator::kOff);
  v.control = controlled(25.0, 1.0);
  v.control.indicator = static_cast<std::uint8_t>(Indicator::kRight);
  EXPECT_EQ(v.indicator(), Indicator::kRight);
}

}  // namespace
}  // namespace entourage
