// The VTISim overtaking decision (thesis section 2.3.3) against values computed by hand.
#include <gtest/gtest.h>

#include <limits>

#include "behaviour/overtaking.hpp"

namespace entourage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTol = 1e-9;

// A passing speed of 1.1 * 25 = 27.5 m/s keeps the hand computations short.
OvertakingParams params() {
  OvertakingParams p;
  p.speed_excess_ratio = 1.1;
  return p;
}

// Following a 20 m/s leader at 20 m/s, 17 m behind it: relative distance
// 17 + 4.5 + 4.5 + (0.6 * 20 + 2) = 40 m.
OvertakingSituation following() {
  OvertakingSituation s;
  s.speed_mps = 20.0;
  s.desired_speed_mps = 25.0;
  s.max_accel_mps2 = 1.0;
  s.length_m = 4.5;
  s.min_gap_m = 2.0;
  s.leader_gap_m = 17.0;
  s.leader_speed_mps = 20.0;
  s.leader_length_m = 4.5;
  return s;
}

// The pass of following(): accelerating 20 -> 27.5 m/s at 1 m/s^2 takes 7.5 s and gains
// 0.5 * 7.5^2 = 28.125 m; the other 11.875 m at 7.5 m/s take 19/12 s, so t_gain = 109/12 s.
// Road: 20 * 7.5 + 28.125 = 178.125, + 27.5 * 19/12, + 27.5 * 2.5 back = 3485/12 m.
constexpr double kFollowingDuration = 109.0 / 12.0 + 2.5;
constexpr double kFollowingDistance = 3485.0 / 12.0;

// --- acceptance curves -----------------------------------------------------------------------

TEST(AcceptanceCurve, InterpolatesLinearlyAndIsConstantBeyondTheEnds) {
  const AcceptanceCurve c{{{100.0, 0.2}, {200.0, 0.6}, {300.0, 0.6}, {400.0, 1.0}}};
  EXPECT_NEAR(c.probability(50.0), 0.2, kTol);
  EXPECT_NEAR(c.probability(100.0), 0.2, kTol);
  EXPECT_NEAR(c.probability(150.0), 0.4, kTol);
  EXPECT_NEAR(c.probability(200.0), 0.6, kTol);
  EXPECT_NEAR(c.probability(250.0), 0.6, kTol);
  EXPECT_NEAR(c.probability(350.0), 0.8, kTol);
  EXPECT_NEAR(c.probability(500.0), 1.0, kTol);
  EXPECT_NEAR(c.probability(kInf), 1.0, kTol);
}

TEST(AcceptanceCurve, ClampsTheResultToAProbability) {
  const AcceptanceCurve c{{{0.0, -0.5}, {100.0, 1.5}}};
  EXPECT_NEAR(c.probability(50.0), 0.5, kTol);
  EXPECT_DOUBLE_EQ(c.probability(10.0), 0.0);  // -0.3 clamped
  EXPECT_DOUBLE_EQ(c.probability(90.0), 1.0);  // 1.3 clamped
  EXPECT_DOUBLE_EQ(c.probability(-100.0), 0.0);
  EXPECT_DOUBLE_EQ(c.probability(kInf), 1.0);
}

TEST(AcceptanceCurve, EmptyAcceptsNothingAndARepeatedGapIsAStep) {
  EXPECT_DOUBLE_EQ(AcceptanceCurve{}.probability(1000.0), 0.0);
  EXPECT_DOUBLE_EQ(AcceptanceCurve{}.probability(kInf), 0.0);
  const AcceptanceCurve step{{{100.0, 0.0}, {100.0, 1.0}}};
  EXPECT_DOUBLE_EQ(step.probability(99.0), 0.0);
  EXPECT_DOUBLE_EQ(step.probability(101.0), 1.0);
}

TEST(AcceptanceCurve, DefaultCurvesFavourFlyingOvertakings) {
  const OvertakingParams p;
  EXPECT_NEAR(p.flying.probability(500.0), 0.5, kTol);        // between 0.3 and 0.7
  EXPECT_NEAR(p.accelerated.probability(600.0), 0.35, kTol);  // between 0.2 and 0.5
  EXPECT_NEAR(p.flying.probability(700.0), 0.8, kTol);
  EXPECT_NEAR(p.accelerated.probability(700.0), 0.5, kTol);
}

// --- relative distance, plan, required gap ---------------------------------------------------

TEST(Overtaking, RelativeDistanceIsGapBothLengthsAndReturnGap) {
  EXPECT_NEAR(relative_distance_to_pass_m(params(), following()), 40.0, kTol);
  OvertakingSituation s;
  s.leader_gap_m = 10.0;
  s.leader_length_m = 12.0;  // a truck
  s.length_m = 4.0;
  s.leader_speed_mps = 15.0;
  s.min_gap_m = 2.5;
  EXPECT_NEAR(relative_distance_to_pass_m(params(), s), 10.0 + 12.0 + 4.0 + 0.6 * 15.0 + 2.5, kTol);
  s.leader_gap_m = -30.0;  // already past
  EXPECT_NEAR(relative_distance_to_pass_m(params(), s), -2.5, kTol);
}

TEST(Overtaking, PlanAcceleratesThenHoldsThePassingSpeed) {
  const PassPlan plan = plan_pass(params(), following());
  ASSERT_TRUE(plan.feasible);
  EXPECT_NEAR(plan.passing_speed_mps, 27.5, kTol);
  EXPECT_NEAR(plan.relative_distance_m, 40.0, kTol);
  EXPECT_NEAR(plan.duration_s, kFollowingDuration, kTol);
  EXPECT_NEAR(plan.distance_m, kFollowingDistance, kTol);
}

TEST(Overtaking, PlanGainsWhileStillAcceleratingFromBelowTheLeadersSpeed) {
  // 15 m/s behind a 20 m/s leader, a = 2, passing speed 1.15 * 30 = 34.5 (reached after 9.75 s).
  // Relative distance 1 + 9 + 14 = 24 m: -5 t + t^2 = 24 at t = 8 s (speed 31 m/s, road
  // 15 * 8 + 64 = 184 m), then 2.5 s back at 31 m/s.
  OvertakingParams p;
  OvertakingSituation s = following();
  s.speed_mps = 15.0;
  s.desired_speed_mps = 30.0;
  s.max_accel_mps2 = 2.0;
  s.leader_gap_m = 1.0;
  const PassPlan plan = plan_pass(p, s);
  ASSERT_TRUE(plan.feasible);
  EXPECT_NEAR(plan.passing_speed_mps, 34.5, kTol);
  EXPECT_NEAR(plan.duration_s, 10.5, kTol);
  EXPECT_NEAR(plan.distance_m, 184.0 + 31.0 * 2.5, kTol);
}

TEST(Overtaking, PlanDuringAPassWithANegativeGap) {
  // 25 m/s, 11 m beside the leader: relative distance 12 m; 5 t + t^2 / 2 = 12 at t = 2 s
  // (speed 27 m/s, road 52 m), then 2.5 s back at 27 m/s.
  OvertakingSituation s = following();
  s.speed_mps = 25.0;
  s.leader_gap_m = -11.0;
  const PassPlan plan = plan_pass(params(), s);
  ASSERT_TRUE(plan.feasible);
  EXPECT_NEAR(plan.relative_distance_m, 12.0, kTol);
  EXPECT_NEAR(plan.duration_s, 4.5, kTol);
  EXPECT_NEAR(plan.distance_m, 52.0 + 27.0 * 2.5, kTol);
}

TEST(Overtaking, PlanAlreadyFarEnoughAheadIsOnlyTheMoveBack) {
  OvertakingSituation s = following();
  s.speed_mps = 25.0;
  s.leader_gap_m = -30.0;  // relative distance -7 m
  const PassPlan plan = plan_pass(params(), s);
  ASSERT_TRUE(plan.feasible);
  EXPECT_NEAR(plan.duration_s, 2.5, kTol);
  EXPECT_NEAR(plan.distance_m, 25.0 * 2.5, kTol);
}

TEST(Overtaking, PassingSpeedIsNeverBelowTheCurrentSpeed) {
  OvertakingSituation s = following();
  s.speed_mps = 30.0;  // above 1.1 * 25
  s.leader_gap_m = 17.0;
  const PassPlan plan = plan_pass(params(), s);
  ASSERT_TRUE(plan.feasible);
  EXPECT_NEAR(plan.passing_speed_mps, 30.0, kTol);
  // 40 m at 10 m/s closing: 4 s, then 2.5 s back.
  EXPECT_NEAR(plan.duration_s, 6.5, kTol);
  EXPECT_NEAR(plan.distance_m, 30.0 * 6.5, kTol);
}

TEST(Overtaking, PlanIsInfeasibleWhenThePassingSpeedDoesNotBeatTheLeaderEnough) {
  OvertakingSituation s = following();
  s.desired_speed_mps = 20.5;  // 1.1 * 20.5 = 22.55 < 20 + 3
  const PassPlan slow = plan_pass(params(), s);
  EXPECT_FALSE(slow.feasible);
  EXPECT_NEAR(slow.relative_distance_m, 40.0, kTol);  // still filled
  s.desired_speed_mps = 21.0;  // 23.1 >= 23
  EXPECT_TRUE(plan_pass(params(), s).feasible);
}

TEST(Overtaking, WithoutAccelerationOnlyAFasterOvertakerCanPass) {
  OvertakingParams p = params();
  p.accel_share = 0.0;
  OvertakingSituation s = following();
  EXPECT_FALSE(plan_pass(p, s).feasible);  // 20 m/s behind 20 m/s, cannot speed up
  s.speed_mps = 24.0;
  const PassPlan plan = plan_pass(p, s);
  ASSERT_TRUE(plan.feasible);
  EXPECT_NEAR(plan.passing_speed_mps, 24.0, kTol);
  EXPECT_NEAR(plan.duration_s, 40.0 / 4.0 + 2.5, kTol);
  EXPECT_NEAR(plan.distance_m, 24.0 * 12.5, kTol);
}

TEST(Overtaking, RequiredGapAddsWhatTheOncomingVehicleCovers) {
  const PassPlan plan = plan_pass(params(), following());
  // 3485/12 + 20 * (139/12 + 3) = 582.08..
  EXPECT_NEAR(required_gap_m(params(), plan, 20.0), 3485.0 / 12.0 + 20.0 * (139.0 / 12.0 + 3.0), kTol);
  EXPECT_NEAR(required_gap_m(params(), plan, 25.0), 655.0, kTol);
  EXPECT_NEAR(required_gap_m(params(), plan, 0.0), kFollowingDistance, kTol);
}

TEST(Overtaking, ClassifiesFlyingByTheClosingSpeed) {
  const OvertakingParams p;  // flying from 1.5 m/s closing
  OvertakingSituation s = following();
  s.speed_mps = 21.5;
  EXPECT_EQ(classify(p, s), OvertakingKind::kFlying);
  s.speed_mps = 21.4;
  EXPECT_EQ(classify(p, s), OvertakingKind::kAccelerated);
  s.speed_mps = 18.0;
  EXPECT_EQ(classify(p, s), OvertakingKind::kAccelerated);
}

// --- the decision ----------------------------------------------------------------------------

TEST(OvertakingDecision, AcceptsALongGapWithALowDraw) {
  OvertakingSituation s = following();
  s.oncoming_distance_m = 1000.0;
  s.oncoming_speed_mps = 20.0;
  const OvertakingDecision d = decide_overtaking(params(), s, 0.0);
  EXPECT_EQ(d.verdict, OvertakingVerdict::kAccepted);
  EXPECT_TRUE(d.accepted());
  EXPECT_EQ(d.kind, OvertakingKind::kAccelerated);
  EXPECT_NEAR(d.available_gap_m, 1000.0, kTol);
  EXPECT_NEAR(d.acceptance_probability, 0.875, kTol);  // 0.8 + 0.15 * 100 / 200
  EXPECT_NEAR(d.plan.distance_m, kFollowingDistance, kTol);
}

TEST(OvertakingDecision, AnEmptyRoadUsesTheCurvesLastValue) {
  const OvertakingDecision d = decide_overtaking(params(), following(), 0.9);
  EXPECT_EQ(d.verdict, OvertakingVerdict::kAccepted);
  EXPECT_TRUE(d.available_gap_m > 1e300);
  EXPECT_NEAR(d.acceptance_probability, 0.95, kTol);
  EXPECT_EQ(decide_overtaking(params(), following(), 0.96).verdict, OvertakingVerdict::kUnwilling);
}

TEST(OvertakingDecision, UnwillingWhenTheDrawIsAboveTheProbability) {
  OvertakingSituation s = following();
  s.oncoming_distance_m = 1000.0;
  s.oncoming_speed_mps = 20.0;
  const OvertakingDecision d = decide_overtaking(params(), s, 0.9);
  EXPECT_EQ(d.verdict, OvertakingVerdict::kUnwilling);
  EXPECT_NEAR(d.acceptance_probability, 0.875, kTol);
  EXPECT_EQ(decide_overtaking(params(), s, 0.874).verdict, OvertakingVerdict::kAccepted);
}

TEST(OvertakingDecision, GapTooShortWhenAnOncomingVehicleIsClose) {
  OvertakingSituation s = following();
  s.oncoming_speed_mps = 20.0;  // needs 582.08 m
  s.oncoming_distance_m = 500.0;
  const OvertakingDecision d = decide_overtaking(params(), s, 0.0);
  EXPECT_EQ(d.verdict, OvertakingVerdict::kGapTooShort);
  EXPECT_TRUE(d.plan.feasible);
  s.oncoming_distance_m = 600.0;
  const OvertakingDecision ok = decide_overtaking(params(), s, 0.0);
  EXPECT_EQ(ok.verdict, OvertakingVerdict::kAccepted);
  EXPECT_NEAR(ok.acceptance_probability, 0.35, kTol);
}

TEST(OvertakingDecision, GapTooShortWhenAVehicleMayBeHiddenBeyondTheSightDistance) {
  OvertakingSituation s = following();  // no oncoming vehicle in sight
  s.sight_distance_m = 600.0;           // one hidden at 25 m/s needs 655 m
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kGapTooShort);
  s.sight_distance_m = 660.0;
  const OvertakingDecision d = decide_overtaking(params(), s, 0.0);
  EXPECT_EQ(d.verdict, OvertakingVerdict::kAccepted);
  EXPECT_NEAR(d.available_gap_m, 660.0, kTol);
  EXPECT_NEAR(d.acceptance_probability, 0.44, kTol);  // 0.2 + 0.3 * 160 / 200
}

TEST(OvertakingDecision, GapTooShortWithoutRoomToReturnInFrontOfTheLeader) {
  OvertakingSituation s = following();
  s.room_ahead_of_leader_m = 18.0;  // needs 4.5 + 12 + 2 = 18.5
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kGapTooShort);
  s.room_ahead_of_leader_m = 18.5;
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kAccepted);
}

TEST(OvertakingDecision, RestrictedWhenANoOvertakingZoneIsNear) {
  OvertakingSituation s = following();  // the pass needs 290.4 m
  s.restriction_free_m = 250.0;
  const OvertakingDecision d = decide_overtaking(params(), s, 0.0);
  EXPECT_EQ(d.verdict, OvertakingVerdict::kRestricted);
  EXPECT_NEAR(d.plan.distance_m, kFollowingDistance, kTol);
  s.restriction_free_m = 300.0;
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kAccepted);
}

TEST(OvertakingDecision, RestrictionOfAnInfeasiblePassUsesTheRelativeDistance) {
  OvertakingSituation s = following();
  s.desired_speed_mps = 20.5;  // infeasible, relative distance 40 m
  s.restriction_free_m = 30.0;
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kRestricted);
  s.restriction_free_m = 50.0;
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kNotCapable);
}

TEST(OvertakingDecision, NotCapableWhenTooSlowOrTheDistanceIsTooLong) {
  OvertakingSituation s = following();
  s.desired_speed_mps = 20.5;
  const OvertakingDecision slow = decide_overtaking(params(), s, 0.0);
  EXPECT_EQ(slow.verdict, OvertakingVerdict::kNotCapable);
  EXPECT_FALSE(slow.plan.feasible);
  OvertakingParams p = params();
  p.max_distance_m = 250.0;  // the pass needs 290.4 m
  EXPECT_EQ(decide_overtaking(p, following(), 0.0).verdict, OvertakingVerdict::kNotCapable);
  p.max_distance_m = 300.0;
  EXPECT_EQ(decide_overtaking(p, following(), 0.0).verdict, OvertakingVerdict::kAccepted);
}

TEST(OvertakingDecision, NoLeaderWhenFarOrNotSlower) {
  OvertakingSituation s = following();
  s.leader_gap_m = 100.0;  // beyond 80 m
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kNoLeader);
  s.leader_gap_m = 80.0;
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kAccepted);
  s = following();
  s.leader_speed_mps = 25.0;  // as fast as the desired speed
  EXPECT_EQ(decide_overtaking(params(), s, 0.0).verdict, OvertakingVerdict::kNoLeader);
}

TEST(OvertakingDecision, FlyingAcceptedWhereAcceleratedIsNotAtTheSameGapAndDraw) {
  // 25 m/s closing on a 20 m/s leader with the default parameters: passing speed 28.75, 3.75 s
  // of acceleration gain 25.78125 m, the other 14.21875 m at 8.75 m/s take 1.625 s; road
  // 100.78125 + 46.71875 + 71.875 = 219.375 m in 7.875 s, so an oncoming vehicle at 20 m/s needs
  // 219.375 + 20 * 10.875 = 436.875 m: at 700 m the gap is long enough for both kinds.
  OvertakingParams flying;
  OvertakingSituation s = following();
  s.speed_mps = 25.0;
  s.oncoming_distance_m = 700.0;
  s.oncoming_speed_mps = 20.0;
  const OvertakingDecision fly = decide_overtaking(flying, s, 0.6);
  EXPECT_EQ(fly.kind, OvertakingKind::kFlying);
  EXPECT_NEAR(fly.plan.duration_s, 7.875, kTol);
  EXPECT_NEAR(fly.plan.distance_m, 219.375, kTol);
  EXPECT_NEAR(fly.acceptance_probability, 0.8, kTol);
  EXPECT_EQ(fly.verdict, OvertakingVerdict::kAccepted);

  OvertakingParams accelerated;
  accelerated.flying_min_closing_mps = 10.0;  // the same situation counts as accelerated
  const OvertakingDecision acc = decide_overtaking(accelerated, s, 0.6);
  EXPECT_EQ(acc.kind, OvertakingKind::kAccelerated);
  EXPECT_NEAR(acc.acceptance_probability, 0.5, kTol);
  EXPECT_EQ(acc.verdict, OvertakingVerdict::kUnwilling);
}

// --- reviewing a pass ------------------------------------------------------------------------

// At 27.5 m/s (the passing speed) in the oncoming lane beside a 20 m/s leader, with an oncoming
// vehicle at 25 m/s.
OvertakingSituation passing(double leader_gap_m, double oncoming_distance_m) {
  OvertakingSituation s = following();
  s.speed_mps = 27.5;
  s.leader_gap_m = leader_gap_m;
  s.oncoming_distance_m = oncoming_distance_m;
  s.oncoming_speed_mps = 25.0;
  return s;
}

TEST(PassReview, ContinuesWhenTheOncomingVehicleIsFar) {
  // Front 2 m beside the leader's rear: 21 m to gain at 7.5 m/s = 2.8 s, + 2.5 s back;
  // 145.75 m of road, and 145.75 + 25 * (5.3 + 1) = 303.25 m needed.
  const PassReview r = review_pass(params(), passing(-2.0, 1000.0));
  EXPECT_EQ(r.action, PassAction::kContinue);
  ASSERT_TRUE(r.remaining.feasible);
  EXPECT_NEAR(r.remaining.duration_s, 5.3, kTol);
  EXPECT_NEAR(r.remaining.distance_m, 145.75, kTol);
  EXPECT_EQ(review_pass(params(), passing(-2.0, 310.0)).action, PassAction::kContinue);
}

TEST(PassReview, AbortsWhenAnOncomingVehicleAppearsCloseBeforeCommitment) {
  EXPECT_EQ(review_pass(params(), passing(-2.0, 300.0)).action, PassAction::kAbort);
  // Rear just behind the leader's middle (commitment at -(4.5 + 0.5 * 4.5) = -6.75 m).
  EXPECT_EQ(review_pass(params(), passing(-6.7, 200.0)).action, PassAction::kAbort);
}

TEST(PassReview, FinishesWhenAlreadyMostlyPast) {
  // Rear 1 m behind the leader's front: 15 m to gain, 2 s + 2.5 s, needing 261.25 m.
  const PassReview r = review_pass(params(), passing(-8.0, 200.0));
  EXPECT_EQ(r.action, PassAction::kContinue);
  EXPECT_NEAR(r.remaining.distance_m, 123.75, kTol);
  EXPECT_EQ(review_pass(params(), passing(-6.75, 200.0)).action, PassAction::kContinue);
}

TEST(PassReview, ReturnsWhenFarEnoughAheadWithRoom) {
  // 25 m past: relative distance -2 m.
  EXPECT_EQ(review_pass(params(), passing(-25.0, 200.0)).action, PassAction::kReturn);
  EXPECT_EQ(review_pass(params(), passing(-23.0, kInf)).action, PassAction::kReturn);  // exactly 0
  EXPECT_EQ(review_pass(params(), passing(-22.0, kInf)).action, PassAction::kContinue);
  OvertakingSituation s = passing(-25.0, kInf);
  s.room_ahead_of_leader_m = 10.0;  // needs 18.5 m: keeps passing
  EXPECT_EQ(review_pass(params(), s).action, PassAction::kContinue);
}

TEST(PassReview, AbortsWhenTheOvertakenVehicleSpeedsUpUnlessCommitted) {
  OvertakingSituation s = passing(-2.0, kInf);
  s.leader_speed_mps = 26.0;  // 27.5 < 26 + 3
  const PassReview r = review_pass(params(), s);
  EXPECT_FALSE(r.remaining.feasible);
  EXPECT_EQ(r.action, PassAction::kAbort);
  s.leader_gap_m = -8.0;
  EXPECT_EQ(review_pass(params(), s).action, PassAction::kContinue);
}

}  // namespace
}  // namespace entourage
