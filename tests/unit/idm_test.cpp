// IDM against its closed forms (Treiber et al. 2000).
#include <gtest/gtest.h>

#include <cmath>

#include "behaviour/car_following.hpp"
#include "behaviour/idm.hpp"
#include "behaviour/modified_idm.hpp"

namespace entourage {
namespace {

IdmParams params() {
  IdmParams p;
  p.desired_speed_mps = 33.3;
  p.time_gap_s = 1.5;
  p.max_accel_mps2 = 1.0;
  p.comfort_decel_mps2 = 1.5;
  p.min_gap_m = 2.0;
  p.accel_exponent = 4.0;
  return p;
}

TEST(Idm, FreeRoadAccelerationIsAOneMinusSpeedRatioToTheDelta) {
  const IdmParams p = params();
  EXPECT_DOUBLE_EQ(idm_free_accel_mps2(p, 0.0), 1.0);
  EXPECT_NEAR(idm_free_accel_mps2(p, 0.5 * 33.3), 1.0 * (1.0 - 0.0625), 1e-12);
  EXPECT_NEAR(idm_free_accel_mps2(p, 33.3), 0.0, 1e-12);
  EXPECT_LT(idm_free_accel_mps2(p, 40.0), 0.0);
}

TEST(Idm, NonIntegerExponentUsesThePowerLaw) {
  IdmParams p = params();
  p.accel_exponent = 2.5;
  EXPECT_NEAR(idm_free_accel_mps2(p, 20.0), 1.0 - std::pow(20.0 / 33.3, 2.5), 1e-12);
}

TEST(Idm, DesiredGapFormula) {
  const IdmParams p = params();
  // s* = s0 + v T + v dv / (2 sqrt(a b))
  EXPECT_NEAR(idm_desired_gap_m(p, 20.0, 5.0), 2.0 + 30.0 + 20.0 * 5.0 / (2.0 * std::sqrt(1.5)), 1e-9);
  // never below s0, even when the leader pulls away fast
  EXPECT_DOUBLE_EQ(idm_desired_gap_m(p, 20.0, -30.0), 2.0);
}

TEST(Idm, EquilibriumGapMatchesClosedForm) {
  const IdmParams p = params();
  for (double v : {1.0, 5.0, 10.0, 20.0, 30.0}) {
    const double se = idm_equilibrium_gap_m(p, v);
    const double expected = (2.0 + v * 1.5) / std::sqrt(1.0 - std::pow(v / 33.3, 4.0));
    EXPECT_NEAR(se, expected, 1e-9) << "v = " << v;
    // and at that gap, behind a leader at the same speed, the acceleration is zero
    EXPECT_NEAR(idm_accel_mps2(p, v, se, v), 0.0, 1e-9) << "v = " << v;
  }
  EXPECT_TRUE(std::isinf(idm_equilibrium_gap_m(p, 33.3)));
}

TEST(Idm, StandstillGapIsMinimumGap) {
  const IdmParams p = params();
  EXPECT_NEAR(idm_equilibrium_gap_m(p, 0.0), 2.0, 1e-12);
  // a stopped car at exactly s0 behind a stopped leader does not move
  EXPECT_NEAR(idm_accel_mps2(p, 0.0, 2.0, 0.0), 0.0, 1e-12);
}

TEST(Idm, ApproachingBrakesHarderThanFollowing) {
  const IdmParams p = params();
  EXPECT_LT(idm_accel_mps2(p, 25.0, 40.0, 15.0), idm_accel_mps2(p, 25.0, 40.0, 25.0));
}

TEST(Idm, FarLeaderBarelyMatters) {
  const IdmParams p = params();
  EXPECT_NEAR(idm_accel_mps2(p, 20.0, 1e6, 20.0), idm_free_accel_mps2(p, 20.0), 1e-6);
}

TEST(CarFollowing, IdmThroughTheInterfaceMatchesIdm) {
  CarFollowingParams cf;
  cf.idm = params();
  const LeaderView leader{30.0, 18.0, 0.0};
  EXPECT_DOUBLE_EQ(car_following_accel_mps2(cf, 20.0, &leader), idm_accel_mps2(cf.idm, 20.0, 30.0, 18.0));
  EXPECT_DOUBLE_EQ(car_following_accel_mps2(cf, 20.0, nullptr), idm_free_accel_mps2(cf.idm, 20.0));
}

}  // namespace
}  // namespace entourage

namespace entourage {
namespace {

TEST(ModifiedIdm, MatchesIdmWhenCloserThanTheDesiredGap) {
  const IdmParams p = params();
  for (double gap : {3.0, 10.0, 20.0}) {
    const double s_star = idm_desired_gap_m(p, 20.0, 2.0);
    ASSERT_LE(gap, s_star);
    EXPECT_DOUBLE_EQ(modified_idm_accel_mps2(p, 1.35, 20.0, gap, 18.0), idm_accel_mps2(p, 20.0, gap, 18.0));
  }
}

TEST(ModifiedIdm, NoInteractionBeyondBetaTimesTheDesiredGap) {
  const IdmParams p = params();
  const double s_star = idm_desired_gap_m(p, 25.0, 0.0);
  EXPECT_DOUBLE_EQ(modified_idm_accel_mps2(p, 1.35, 25.0, 1.35 * s_star, 25.0), idm_free_accel_mps2(p, 25.0));
  EXPECT_DOUBLE_EQ(modified_idm_accel_mps2(p, 1.35, 25.0, 3.0 * s_star, 25.0), idm_free_accel_mps2(p, 25.0));
  // IDM still brakes there
  EXPECT_LT(idm_accel_mps2(p, 25.0, 1.35 * s_star, 25.0), idm_free_accel_mps2(p, 25.0) - 0.3);
}

TEST(ModifiedIdm, IsContinuousWhereTheWeightChanges) {
  const IdmParams p = params();
  const double v = 25.0;
  const double s_star = idm_desired_gap_m(p, v, 0.0);
  const double eps = 1e-7;
  for (double at : {s_star, 1.35 * s_star}) {
    EXPECT_NEAR(modified_idm_accel_mps2(p, 1.35, v, at - eps, v), modified_idm_accel_mps2(p, 1.35, v, at + eps, v), 1e-5)
        << "at gap " << at;
  }
  // and in between, more room never means more braking
  double previous = modified_idm_accel_mps2(p, 1.35, v, s_star, v);
  for (double gap = s_star; gap <= 1.5 * s_star; gap += 0.01) {
    const double a = modified_idm_accel_mps2(p, 1.35, v, gap, v);
    EXPECT_GE(a, previous - 1e-12) << "gap " << gap;
    previous = a;
  }
}

TEST(ModifiedIdm, ReachesTheDesiredSpeedWhereIdmCannot) {
  // equilibrium at a 100 m gap: IDM settles well below v0, the modified model at v0
  CarFollowingParams idm;
  idm.idm = params();
  CarFollowingParams mod = idm;
  mod.model = CarFollowingModel::kModifiedIdm;
  const LeaderView far{100.0, 33.3, 0.0};  // a leader 100 m ahead at the desired speed
  double v_idm = 33.3;
  double v_mod = 33.3;
  for (int i = 0; i < 3000; ++i) {
    v_idm += 0.1 * car_following_accel_mps2(idm, v_idm, &far);
    v_mod += 0.1 * car_following_accel_mps2(mod, v_mod, &far);
  }
  EXPECT_LT(v_idm, 33.3 - 1.0);
  EXPECT_NEAR(v_mod, 33.3, 0.05);
}

}  // namespace
}  // namespace entourage
