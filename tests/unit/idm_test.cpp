// IDM against its closed forms (Treiber et al. 2000).
#include <gtest/gtest.h>

#include <cmath>

#include "behaviour/car_following.hpp"
#include "behaviour/idm.hpp"

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
