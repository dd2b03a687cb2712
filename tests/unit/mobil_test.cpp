// MOBIL's decision (Kesting et al. 2007), in formula form and in situations built by hand.
#include <gtest/gtest.h>

#include <limits>

#include "behaviour/mobil.hpp"
#include "core_test_util.hpp"
#include "traffic/driving.hpp"
#include "traffic/fleet.hpp"
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

// MOBIL's new follower is judged by its own model where the service drives it (the index's
// drivers), by the changer's parameters otherwise: a gentle changer (a = 1.0 m/s^2, T = 0.9 s)
// finds 15 m in front of a car at its own speed safe by its own standards (about -2.1 m/s^2),
// which that car's own model (a = 2.0 m/s^2, T = 1.6 s) answers with braking far beyond b_safe.
TEST_F(LaneChangeSituation, TheNewFollowerIsJudgedByItsOwnModelWhereThisServiceDrivesIt) {
  Vehicle me = car(1, 0, 1000.0, 26.0, 36.0);
  me.driver.car_following.idm.max_accel_mps2 = 1.0;
  me.driver.car_following.idm.time_gap_s = 0.9;
  Vehicle follower = car(3, 1, 1000.0 - 4.5 - 15.0, 26.0, 36.0);
  follower.driver.car_following.idm.max_accel_mps2 = 2.0;
  follower.driver.car_following.idm.time_gap_s = 1.6;
  add(me);
  add(car(2, 0, 1040.0, 20.0, 20.0));  // a slower car ahead: the change pays
  add(follower);
  index.sort();
  const double judged_by_me = follower_accel_mps2(me.driver.car_following, {3, follower.s_m, 26.0, 0.0, 4.5},
                                                  &index.lane(Direction::kForward, 0)[0]);
  EXPECT_GT(judged_by_me, -me.driver.mobil.safe_decel_mps2);
  EXPECT_TRUE(evaluate_lane_change(me, index, 1).safe);  // nobody's drivers known

  Fleet drivers;
  Handoff h;
  h.vehicle = follower;
  drivers.adopt(h, 0, 0.1);
  index.set_drivers(&drivers);
  EXPECT_EQ(&model_of(3, index, me.driver.car_following), &drivers.find(3)->driver.car_following);
  EXPECT_EQ(&model_of(2, index, me.driver.car_following), &me.driver.car_following);  // not driven here
  EXPECT_LT(follower_accel_mps2(follower.driver.car_following, {3, follower.s_m, 26.0, 0.0, 4.5},
                                &index.lane(Direction::kForward, 0)[0]),
            -2.0 * me.driver.mobil.safe_decel_mps2);
  EXPECT_FALSE(evaluate_lane_change(me, index, 1).safe);
  const LaneIndex copy = index;  // a copied core's index must not point into the original's fleet
  EXPECT_EQ(copy.drivers(), nullptr);
  EXPECT_TRUE(evaluate_lane_change(me, copy, 1).safe);
  index.clear();
  EXPECT_EQ(index.drivers(), nullptr);
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

// Cast as an actor for the lane it was signalling to leave, a car changed out and back (cut-in,
// seed 1): a vehicle the director moves calls off a change it is no longer asked for.
TEST_F(LaneChangeSituation, AVehicleTheDirectorNoLongerAsksToChangeLanesCallsOffItsSignal) {
  Vehicle me = car(1, 0, 1000.0, 28.0, 33.0);
  me.control.mode = ControlMode::kTransported;
  me.control.speed_mps = kOwnDesiredSpeed_mps;
  me.control.lane = 1;
  add(me);
  index.sort();
  Decision d = decide(me, index, env);
  ASSERT_EQ(d.lane_change.phase, LaneChangePhase::kSignalling);
  EXPECT_EQ(d.lane_change.to_lane, 1);
  me.lane_change = d.lane_change;
  // Still asked for lane 1: it goes on signalling.
  EXPECT_EQ(decide(me, index, env).lane_change.phase, LaneChangePhase::kSignalling);
  me.control.lane = 0;  // now asked to keep its lane
  d = decide(me, index, env);
  EXPECT_EQ(d.lane_change.phase, LaneChangePhase::kNone);
  EXPECT_EQ(d.lane_change.to_lane, 0);
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

// --- A vehicle the director asks to change lanes finds its gap by speed (gap_seeking_cap_mps2)

class GapSeeking : public LaneChangeSituation {
 protected:
  // Car 1 in the right lane, asked (transported, at its own speed) to move left, indicator on.
  Vehicle seeker(double s, double v) {
    Vehicle c = car(1, 0, s, v, 33.0);
    c.control.mode = ControlMode::kTransported;
    c.control.speed_mps = kOwnDesiredSpeed_mps;
    c.control.lane = 1;
    c.lane_change.phase = LaneChangePhase::kSignalling;
    c.lane_change.to_lane = 1;
    return c;
  }
  void add_signalling(const Vehicle& v, int signal) {
    index.add(Direction::kForward, v.lane, {v.id, v.s_m, v.speed_mps, 0.0, v.length_m, signal});
  }
  double cap(const Vehicle& v) { return gap_seeking_cap_mps2(v, v.driver.car_following, index, v.lane_change); }
};

TEST_F(GapSeeking, ItDropsBackFromACarBesideItThenHoldsALittleBelowItsSpeed) {
  Vehicle me = seeker(1000.0, 28.0);
  add(me);
  add(car(2, 1, 1002.0, 28.0, 33.0));  // beside it in the target lane
  index.sort();
  EXPECT_DOUBLE_EQ(cap(me), -me.driver.car_following.idm.comfort_decel_mps2);
  me.speed_mps = 22.0;  // 6 m/s slower: it holds that speed until the car has passed
  EXPECT_DOUBLE_EQ(cap(me), 0.0);
}

TEST_F(GapSeeking, ACarJustBehindThatLeavesNoSafeGapIsLetBy) {
  const Vehicle me = seeker(1000.0, 28.0);
  add(me);
  add(car(2, 1, 992.0, 30.0, 33.0));  // 3.5 m behind its rear, faster: changing now is unsafe
  index.sort();
  EXPECT_FALSE(evaluate_lane_change(me, index, 1).safe);
  EXPECT_LT(cap(me), 0.0);
}

TEST_F(GapSeeking, AGapOnlyTooShortBecauseItIsSlowerIsClosedByMatchingSpeedNotByLettingBy) {
  Vehicle me = seeker(1000.0, 22.0);
  add(me);
  add(car(2, 1, 960.0, 30.0, 33.0));  // 35.5 m behind its rear, 8 m/s faster
  index.sort();
  EXPECT_FALSE(evaluate_lane_change(me, index, 1).safe);
  // At that car's speed the gap would be safe: it speeds up (nothing ahead there) instead of
  // falling back, which had left it below the lane's speed for good.
  EXPECT_EQ(cap(me), std::numeric_limits<double>::infinity());
}

TEST_F(GapSeeking, ASlowerCarBesideItIsNotLetByItMayBeHoldingBackToLetItIn) {
  const Vehicle me = seeker(1000.0, 28.0);
  add(me);
  add(car(2, 1, 999.0, 26.0, 33.0));  // beside it, 2 m/s slower (the director's let-in)
  index.sort();
  EXPECT_EQ(cap(me), std::numeric_limits<double>::infinity());
}

// One still faster but braking to below its speed within 2 s is holding back too: judged by its
// speed alone, the two braked each other down (lead vehicle, seed 18: from 24 to 1 m/s).
TEST_F(GapSeeking, ACarBesideItBrakingToBelowItsSpeedIsNotLetBy) {
  const Vehicle me = seeker(1000.0, 24.0);
  add(me);
  index.add(Direction::kForward, 1, {2, 999.0, 25.0, -1.0, 4.5, 0});  // 1 m/s faster, braking at 1 m/s2
  index.sort();
  EXPECT_EQ(cap(me), std::numeric_limits<double>::infinity());
}

TEST_F(GapSeeking, ACarBesideItBrakingOnlyALittleIsStillLetBy) {
  const Vehicle me = seeker(1000.0, 24.0);
  add(me);
  index.add(Direction::kForward, 1, {2, 999.0, 25.0, -0.2, 4.5, 0});  // still faster in 2 s
  index.sort();
  EXPECT_LT(cap(me), 0.0);
}

TEST_F(GapSeeking, OfTwoThatWantEachOthersLaneTheOneBehindGivesWay) {
  // Car 2 beside and a little behind wants the right lane (indicator right): car 1 does not let it
  // by (each letting the other by braked both to a standstill), car 2 drops back behind car 1.
  const Vehicle me = seeker(1000.0, 28.0);
  add(me);
  Vehicle other = car(2, 1, 998.0, 28.0, 33.0);
  other.control = me.control;
  other.control.lane = 0;
  other.lane_change.phase = LaneChangePhase::kSignalling;
  other.lane_change.to_lane = 0;
  add_signalling(other, -1);
  index.sort();
  EXPECT_EQ(cap(me), std::numeric_limits<double>::infinity());
  EXPECT_LT(gap_seeking_cap_mps2(other, other.driver.car_following, index, other.lane_change), 0.0);
}

TEST_F(GapSeeking, ItEasesInBehindTheCarAheadInTheTargetLane) {
  const Vehicle me = seeker(1000.0, 28.0);
  add(me);
  add(car(2, 1, 1020.0, 22.0, 22.0));  // 15.5 m ahead in the target lane, slower
  index.sort();
  const double c = cap(me);
  EXPECT_LT(c, 0.0);
  EXPECT_GE(c, -me.driver.car_following.idm.comfort_decel_mps2);
}

TEST_F(GapSeeking, OnlyVehiclesAskedToChangeLanesAtTheirOwnSpeedSeekAGap) {
  Vehicle me = seeker(1000.0, 28.0);
  add(me);
  add(car(2, 1, 1002.0, 28.0, 33.0));
  index.sort();
  Vehicle actor = me;
  actor.control.speed_mps = 30.0;  // an actor on its way: its speed is the plan's
  EXPECT_EQ(cap(actor), std::numeric_limits<double>::infinity());
  Vehicle autonomous = me;
  autonomous.control = ActorControl{};
  EXPECT_EQ(cap(autonomous), std::numeric_limits<double>::infinity());
  me.lane_change.phase = LaneChangePhase::kMoving;  // already moving over
  EXPECT_EQ(cap(me), std::numeric_limits<double>::infinity());
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
