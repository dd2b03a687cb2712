// MOBIL's decision (Kesting et al. 2007), in formula form and in situations built by hand.
#include <gtest/gtest.h>

#include "behaviour/mobil.hpp"
#include "core_test_util.hpp"
#include "traffic/driving.hpp"
#include "traffic/lane_changes.hpp"
#include "traffic/lane_index.hpp"

namespace entourage {
namespace {

TEST(Mobil, ChangesWhenOwnGainExceedsThresholdAndBias) {
  MobilParams p;  // politeness 0.2, threshold 0.1, right bias 0.3, b_safe 4
  MobilSituation s;
  s.to_right = false;
  s.self_now_mps2 = -1.0;
  s.self_after_mps2 = 0.5;  // gain 1.5 > 0.1 + 0.3
  EXPECT_TRUE(mobil_decide(p, s).change);
  EXPECT_NEAR(mobil_decide(p, s).advantage_mps2, 1.5 - 0.1 - 0.3, 1e-12);
}

TEST(Mobil, RightBiasMakesChangesToTheRightEasier) {
  MobilParams p;
  MobilSituation s;
  s.self_now_mps2 = 0.0;
  s.self_after_mps2 = 0.0;  // no own gain
  s.to_right = true;
  EXPECT_TRUE(mobil_decide(p, s).change);  // 0 - 0.1 + 0.3 > 0
  s.to_right = false;
  EXPECT_FALSE(mobil_decide(p, s).change);  // 0 - 0.1 - 0.3 < 0
}

TEST(Mobil, PolitenessWeighsTheFollowersLoss) {
  MobilParams p;
  p.politeness = 1.0;
  MobilSituation s;
  s.self_now_mps2 = 0.0;
  s.self_after_mps2 = 1.0;
  s.new_follower_now_mps2 = 0.0;
  s.new_follower_after_mps2 = -1.0;  // the new follower loses as much as we gain
  EXPECT_FALSE(mobil_decide(p, s).change);
  p.politeness = 0.0;  // an egoistic driver changes anyway
  EXPECT_TRUE(mobil_decide(p, s).change);
}

TEST(Mobil, UnsafeChangeIsRefusedWhateverTheGain) {
  MobilParams p;
  MobilSituation s;
  s.self_now_mps2 = -3.0;
  s.self_after_mps2 = 1.0;
  s.new_follower_after_mps2 = -5.0;  // below -b_safe
  const MobilDecision d = mobil_decide(p, s);
  EXPECT_FALSE(d.safe);
  EXPECT_FALSE(d.change);
}

// Hand-built two-lane situations through the full evaluation (IDM accelerations, lane index).
class LaneChangeSituation : public ::testing::Test {
 protected:
  LaneIndex index{2, 0};
  DrivingEnvironment env{testing::road_scenario(2, 0)};

  Vehicle car(VehicleId id, int lane, double s, double v, double v0) {
    Vehicle c;
    c.id = id;
    c.lane = lane;
    c.s_m = s;
    c.speed_mps = v;
    c.length_m = 4.5;
    c.driver.car_following.idm.desired_speed_mps = v0;
    c.lane_change.from_lane = c.lane_change.to_lane = lane;
    return c;
  }
  void add(const Vehicle& v) { index.add(Direction::kForward, v.lane, {v.id, v.s_m, v.speed_mps, 0.0, v.length_m}); }
};

TEST_F(LaneChangeSituation, FastCarBehindTruckOvertakesIntoAnEmptyLane) {
  const Vehicle me = car(1, 0, 1000.0, 30.0, 36.0);
  add(me);
  add(car(2, 0, 1040.0, 22.0, 22.0));  // slow truck 40 m ahead
  index.sort();
  const LaneChangeOption opt = evaluate_lane_change(me, index, 1);
  EXPECT_TRUE(opt.safe);
  EXPECT_GT(opt.advantage_mps2, 0.0);
}

TEST_F(LaneChangeSituation, NoChangeIntoAGapOccupiedByACarBeside) {
  const Vehicle me = car(1, 0, 1000.0, 30.0, 36.0);
  add(me);
  add(car(2, 0, 1040.0, 22.0, 22.0));
  add(car(3, 1, 1002.0, 30.0, 36.0));  // right beside us in the left lane
  index.sort();
  EXPECT_FALSE(evaluate_lane_change(me, index, 1).safe);
}

TEST_F(LaneChangeSituation, NoChangeInFrontOfAFastCloseFollower) {
  const Vehicle me = car(1, 0, 1000.0, 25.0, 36.0);
  add(me);
  add(car(2, 0, 1030.0, 20.0, 20.0));
  add(car(3, 1, 985.0, 38.0, 40.0));  // 10 m behind in the left lane, 13 m/s faster
  index.sort();
  const LaneChangeOption opt = evaluate_lane_change(me, index, 1);
  EXPECT_FALSE(opt.safe);
}

TEST_F(LaneChangeSituation, FreeCarReturnsToTheRightLane) {
  const Vehicle me = car(1, 1, 1000.0, 33.0, 33.3);
  add(me);
  index.sort();
  const LaneChangeOption opt = evaluate_lane_change(me, index, 0);
  EXPECT_TRUE(opt.safe);
  EXPECT_GT(opt.advantage_mps2, 0.0);  // only the right bias, but that is enough
}

TEST_F(LaneChangeSituation, DecisionSignalsFirstThenMovesWhenSafe) {
  Vehicle me = car(1, 0, 1000.0, 30.0, 36.0);
  add(me);
  add(car(2, 0, 1040.0, 22.0, 22.0));
  index.sort();
  const DrivingRules& rules = env.rules();
  Decision d = decide(me, index, env);
  ASSERT_EQ(d.lane_change.phase, LaneChangePhase::kSignalling);
  EXPECT_EQ(d.lane_change.to_lane, 1);
  me.lane_change = d.lane_change;
  me.lane_change.phase_elapsed_s = rules.signal_s;  // the indicator has been on long enough
  d = decide(me, index, env);
  EXPECT_EQ(d.lane_change.phase, LaneChangePhase::kMoving);
}

TEST_F(LaneChangeSituation, KeepRightVehiclesNeverMoveLeft) {
  Vehicle truck = car(1, 0, 1000.0, 22.0, 25.0);
  truck.driver.keep_right = true;
  add(truck);
  add(car(2, 0, 1030.0, 15.0, 15.0));
  index.sort();
  const Decision d = decide(truck, index, env);
  EXPECT_EQ(d.lane_change.phase, LaneChangePhase::kNone);
}

TEST(EmergencyRegime, BrakesHardEnoughToStopBehindAStoppedCar) {
  Vehicle v;
  v.id = 1;
  v.s_m = 0.0;
  v.speed_mps = 30.0;
  v.length_m = 4.5;
  v.driver.max_decel_mps2 = 9.0;
  const Occupant stopped{2, 60.0, 0.0, 0.0, 4.5};  // 55.5 m ahead, standing
  const double a = accel_behind(v, &stopped);
  // stopping within the gap needs v^2 / (2 (gap - 0.5)) = 900 / 110 = 8.18 m/s^2, and the vehicle
  // can brake 9 m/s^2 at most
  EXPECT_LE(a, -8.18);
  EXPECT_GE(a, -9.0);
}

}  // namespace
}  // namespace entourage
