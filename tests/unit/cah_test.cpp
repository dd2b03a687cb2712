// The ACC model's constant-acceleration heuristic and blend (behaviour/cah.hpp, Kesting, Treiber &
// Helbing 2010): its two cases, the blend's bounds, equilibrium unchanged, and the situation that
// motivated it (a follower judged in MOBIL).
#include <gtest/gtest.h>

#include <cmath>

#include "behaviour/cah.hpp"
#include "behaviour/car_following.hpp"
#include "behaviour/idm.hpp"

namespace entourage {
namespace {

CarFollowingParams stand_in(double coolness) {
  CarFollowingParams p;
  p.model = CarFollowingModel::kIdm;
  p.idm.desired_speed_mps = 110.0 / 3.6;
  p.idm.time_gap_s = 1.5;
  p.idm.max_accel_mps2 = 1.0;
  p.idm.comfort_decel_mps2 = 1.5;
  p.idm.min_gap_m = 2.0;
  p.coolness = coolness;
  return p;
}

TEST(Cah, ALeaderThatStopsFirstIsStoppedForJustBehindIt) {
  // v_l (v - v_l) = 100 <= -2 s a~ = 180: the leader stops within the gap; a = v^2 a~ / (v_l^2 - 2 s a~)
  EXPECT_NEAR(cah_accel_mps2(1.5, 20.0, 30.0, 10.0, -3.0), 400.0 * -3.0 / (100.0 + 180.0), 1e-12);
}

TEST(Cah, OtherwiseTheClosingSpeedIsShedOverTheGap) {
  // a~ - (v - v_l)^2 / (2 s), with a~ = min(a_l, a)
  EXPECT_NEAR(cah_accel_mps2(1.0, 31.0, 59.0, 23.4, 0.0), -7.6 * 7.6 / 118.0, 1e-12);
  EXPECT_NEAR(cah_accel_mps2(1.0, 31.0, 59.0, 23.4, 2.0), 1.0 - 7.6 * 7.6 / 118.0, 1e-12);
  // a leader pulling away (v_l (v - v_l) = -125 <= -2 s a~ = -10): the first case, below a~
  EXPECT_NEAR(cah_accel_mps2(1.0, 20.0, 10.0, 25.0, 0.5), 400.0 * 0.5 / (625.0 - 10.0), 1e-12);
  // the leader's acceleration counts only up to the driver's own
  EXPECT_NEAR(cah_accel_mps2(1.0, 31.0, 59.0, 23.4, 3.0), cah_accel_mps2(1.0, 31.0, 59.0, 23.4, 1.0), 1e-12);
}

TEST(Cah, TheBlendLiesBetweenIdmAndTheHeuristicAndKeepsIdmWhereItIsMilder) {
  for (double idm : {-9.0, -4.0, -1.0, 0.0, 0.5}) {
    for (double cah : {-3.0, -0.5, 0.0, 1.0}) {
      const double a = acc_blend_mps2(idm, cah, 0.99, 1.5);
      if (idm >= cah) {
        EXPECT_EQ(a, idm);
      } else {
        EXPECT_GT(a, idm) << idm << " " << cah;
        EXPECT_LT(a, cah) << idm << " " << cah;
      }
    }
  }
  EXPECT_EQ(acc_blend_mps2(-6.0, -0.5, 0.0, 1.5), -6.0);  // coolness 0: IDM
}

TEST(Cah, EquilibriumIsIdmsOwn) {
  const CarFollowingParams with = stand_in(0.99);
  for (double v : {5.0, 15.0, 25.0}) {
    const double gap = idm_equilibrium_gap_m(with.idm, v);
    const LeaderView leader{gap, v, 0.0};
    EXPECT_NEAR(car_following_accel_mps2(with, v, &leader), 0.0, 1e-9) << v;
  }
}

TEST(Cah, AFollowerClosingFromFarBrakesGentlyInsteadOfHard) {
  // 59 m behind a car changing into its lane 7.6 m/s slower: IDM with the stand-in's parameters
  // brakes at about 6 m/s^2 (more than MOBIL's b_safe = 4, so the change is refused), though 0.5
  // m/s^2 would shed the closing speed over the gap.
  const LeaderView changer{59.0, 23.4, 0.0};
  const double idm = car_following_accel_mps2(stand_in(0.0), 31.0, &changer);
  const double acc = car_following_accel_mps2(stand_in(0.99), 31.0, &changer);
  EXPECT_LT(idm, -4.0);
  EXPECT_GT(acc, -4.0);
  EXPECT_LT(acc, -7.6 * 7.6 / 118.0);  // still brakes more than the bare kinematic need
  // and close in, closing fast, it brakes as hard as IDM would, near enough
  const LeaderView close{8.0, 15.0, 0.0};
  const double idm_close = car_following_accel_mps2(stand_in(0.0), 28.0, &close);
  const double acc_close = car_following_accel_mps2(stand_in(0.99), 28.0, &close);
  EXPECT_LT(acc_close, -9.0);
  EXPECT_GE(acc_close, idm_close);
}

}  // namespace
}  // namespace entourage
