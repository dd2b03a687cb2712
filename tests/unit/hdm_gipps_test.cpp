// The Human Driver Model (Treiber et al. 2006) and Gipps (1981) against their closed forms and
// hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "behaviour/car_following.hpp"
#include "behaviour/gipps.hpp"
#include "behaviour/hdm.hpp"
#include "behaviour/modified_idm.hpp"

namespace entourage {
namespace {

CarFollowingParams base(CarFollowingModel m = CarFollowingModel::kIdm) {
  CarFollowingParams p;
  p.model = m;
  p.idm = {33.3, 1.5, 1.0, 1.5, 2.0, 4.0};
  p.beta = 1.35;
  return p;
}

HdmParams exact() {  // no delay, no errors, one leader: the base model
  HdmParams h;
  h.reaction_time_s = 0.0;
  h.anticipated_leaders = 1;
  h.distance_error = 0.0;
  h.inverse_ttc_error_per_s = 0.0;
  return h;
}

TEST(Hdm, WithoutDelayErrorsAndFurtherLeadersIsTheBaseModel) {
  const HdmErrors e{1.3, -0.7};  // errors have no effect when their magnitudes are zero
  for (CarFollowingModel m : {CarFollowingModel::kIdm, CarFollowingModel::kModifiedIdm}) {
    const CarFollowingParams p = base(m);
    for (double gap : {5.0, 20.0, 45.0, 80.0, 200.0}) {
      const LeaderView l{gap, 24.0, 0.0};
      EXPECT_NEAR(hdm_instant_accel_mps2(p, exact(), e, 28.0, &l, 1), car_following_accel_mps2(p, 28.0, &l), 1e-12)
          << "gap " << gap;
    }
    EXPECT_NEAR(hdm_instant_accel_mps2(p, exact(), e, 28.0, nullptr, 0), car_following_accel_mps2(p, 28.0, nullptr),
                1e-12);
  }
}

TEST(Hdm, SeveralLeadersKeepTheHomogeneousEquilibriumOfPointVehicles) {
  // Point-like vehicles at equal gaps s: the j-th leader is j s away and its IDM interaction is
  // a_int(s) / j^2, so the normalised sum is a_int(s) exactly.
  CarFollowingParams p = base();
  HdmParams h = exact();
  h.anticipated_leaders = 3;
  const double s = 40.0;
  const std::vector<LeaderView> leaders{{s, 25.0, 0.0}, {2 * s, 25.0, 0.0}, {3 * s, 25.0, 0.0}};
  EXPECT_NEAR(hdm_instant_accel_mps2(p, h, HdmErrors{}, 25.0, leaders.data(), 3),
              car_following_accel_mps2(p, 25.0, &leaders[0]), 1e-12);
  // At IDM's equilibrium gap the HDM driver with three leaders is in equilibrium too.
  const double se = idm_equilibrium_gap_m(p.idm, 25.0);
  const std::vector<LeaderView> eq{{se, 25.0, 0.0}, {2 * se, 25.0, 0.0}, {3 * se, 25.0, 0.0}};
  EXPECT_NEAR(hdm_instant_accel_mps2(p, h, HdmErrors{}, 25.0, eq.data(), 3), 0.0, 1e-9);
}

TEST(Hdm, ABrakingSecondLeaderIsSeenThroughTheFirst) {
  CarFollowingParams p = base();
  HdmParams h = exact();
  h.anticipated_leaders = 2;
  const std::vector<LeaderView> calm{{40.0, 25.0, 0.0}, {85.0, 25.0, 0.0}};
  const std::vector<LeaderView> jam{{40.0, 25.0, 0.0}, {30.0 + 40.0 + 4.5, 5.0, 0.0}};
  EXPECT_LT(hdm_instant_accel_mps2(p, h, HdmErrors{}, 25.0, jam.data(), 2),
            hdm_instant_accel_mps2(p, h, HdmErrors{}, 25.0, calm.data(), 2) - 0.5);
}

TEST(Hdm, EstimationErrorsScaleTheGapAndTheApproachRate) {
  CarFollowingParams p = base();
  HdmParams h = exact();
  h.distance_error = 0.1;
  h.inverse_ttc_error_per_s = 0.01;
  const LeaderView l{50.0, 25.0, 0.0};
  // w_s = 1: the gap looks exp(0.1) times longer; w_r = 1: the approach looks 50 * 0.01 = 0.5 m/s slower.
  const HdmErrors e{1.0, 1.0};
  const double expected = idm_free_accel_mps2(p.idm, 28.0) +
                          idm_interaction_mps2(p.idm, 28.0, 50.0 * std::exp(0.1), 25.0 + 0.5);
  EXPECT_NEAR(hdm_instant_accel_mps2(p, h, e, 28.0, &l, 1), expected, 1e-12);
}

TEST(Hdm, ErrorProcessesAreStationaryWithTheirPersistence) {
  HdmParams h;
  h.error_persistence_s = 20.0;
  SmallRandom rng(12345);
  HdmErrors e;
  const double dt = 0.1;
  double sum2 = 0.0;
  double lag = 0.0;
  const int n = 400000;
  double prev = 0.0;
  for (int i = 0; i < n; ++i) {
    advance_hdm_errors(e, h, dt, rng);
    sum2 += e.w_distance * e.w_distance;
    lag += e.w_distance * prev;
    prev = e.w_distance;
  }
  EXPECT_NEAR(sum2 / n, 1.0, 0.1);                       // unit variance
  EXPECT_NEAR(lag / sum2, std::exp(-dt / 20.0), 0.002);  // one-step correlation exp(-dt / tau)
}

TEST(HdmMemory, DelaysDecisionsByTheReactionTimeWithInterpolation) {
  HdmMemory m;
  for (int k = 0; k < 10; ++k) m.push(k);  // decided 0, 1, ..., 9 (9 the newest)
  const double now = 10.0;
  EXPECT_DOUBLE_EQ(m.delayed(now, 0.0, 0.1), 10.0);
  EXPECT_NEAR(m.delayed(now, 0.6, 0.1), 4.0, 1e-9);   // six steps ago
  EXPECT_NEAR(m.delayed(now, 0.65, 0.1), 3.5, 1e-9);  // half-way between 4 and 3
  EXPECT_NEAR(m.delayed(now, 5.0, 0.1), 0.0, 1e-9);   // beyond the memory: the oldest known
  HdmMemory fresh;
  EXPECT_DOUBLE_EQ(fresh.delayed(3.0, 0.6, 0.1), 3.0);  // nothing remembered yet: the current one
}

TEST(HdmMemory, KeepsItsCapacity) {
  HdmMemory m;
  for (int k = 0; k < 100; ++k) m.push(k);
  EXPECT_EQ(m.count, HdmMemory::kCapacity);
  EXPECT_FLOAT_EQ(m.decided_mps2[0], 99.0f);
  EXPECT_FLOAT_EQ(m.decided_mps2[HdmMemory::kCapacity - 1], 100.0f - HdmMemory::kCapacity);
}

GippsParams gipps() {
  GippsParams g;
  g.reaction_time_s = 2.0 / 3.0;
  g.max_decel_mps2 = 3.0;
  g.leader_decel_estimate_mps2 = 3.0;
  return g;
}

TEST(Gipps, SafeSpeedByHand) {
  // b = 3, tau = 2/3, gap 30 m, s0 2 m, v 20, leader 15:
  //   b^2 tau^2 = 4;  2 (gap - s0) - v tau + v_l^2 / b_hat = 56 - 13.333 + 75 = 117.667
  //   v_b = -2 + sqrt(4 + 353) = 16.894
  const IdmParams idm = base().idm;
  EXPECT_NEAR(gipps_safe_speed_mps(idm, gipps(), 20.0, 30.0, 15.0), -2.0 + std::sqrt(357.0), 1e-9);
  // A standing leader 10 m ahead: v_b = -2 + sqrt(4 + 3 (16 - 13.333)) = 1.4641
  EXPECT_NEAR(gipps_safe_speed_mps(idm, gipps(), 20.0, 10.0, 0.0), -2.0 + std::sqrt(4.0 + 3.0 * (16.0 - 40.0 / 3.0)),
              1e-9);
}

TEST(Gipps, FreeSpeedByHand) {
  // v + 2.5 a tau (1 - v/v0) sqrt(0.025 + v/v0) with v0 = 33.3, a = 1, v = 20
  const IdmParams idm = base().idm;
  const double r = 20.0 / 33.3;
  EXPECT_NEAR(gipps_free_speed_mps(idm, gipps(), 20.0), 20.0 + 2.5 * (2.0 / 3.0) * (1.0 - r) * std::sqrt(0.025 + r),
              1e-12);
  EXPECT_NEAR(gipps_free_speed_mps(idm, gipps(), 33.3), 33.3, 1e-12);  // at the desired speed: stays
}

TEST(Gipps, SafeSpeedKeepsTheStoppingCondition) {
  // Gipps' derivation: from v now and v' after tau, with a further tau/2 of reaction before
  // braking at b, the follower covers (v + v') tau / 2 + v' tau / 2 + v'^2 / (2 b), which must not
  // exceed gap - s0 + v_l^2 / (2 b_hat). The safe speed makes it an equality.
  const IdmParams idm = base().idm;
  const GippsParams g = gipps();
  const double tau = g.reaction_time_s;
  for (double gap : {10.0, 25.0, 60.0}) {
    for (double vl : {0.0, 10.0, 25.0}) {
      const double v = 25.0;
      const double vb = gipps_safe_speed_mps(idm, g, v, gap, vl);
      const double need = (v + vb) * tau / 2.0 + vb * tau / 2.0 + vb * vb / (2.0 * g.max_decel_mps2);
      const double room = gap - idm.min_gap_m + vl * vl / (2.0 * g.leader_decel_estimate_mps2);
      if (vb > 0.0) {
        EXPECT_NEAR(need, room, 1e-9) << "gap " << gap << " leader " << vl;
      } else {  // too close for any speed to be safe: stop
        EXPECT_GT(need, room) << "gap " << gap << " leader " << vl;
      }
    }
  }
}

TEST(Gipps, ThroughTheInterfaceFollowsTheLowerSpeed) {
  CarFollowingParams p = base(CarFollowingModel::kGipps);
  p.gipps = gipps();
  EXPECT_NEAR(car_following_accel_mps2(p, 33.3, nullptr), 0.0, 1e-12);
  const LeaderView close{30.0, 15.0, 0.0};
  const double vb = gipps_safe_speed_mps(p.idm, p.gipps, 20.0, 30.0, 15.0);
  EXPECT_NEAR(car_following_accel_mps2(p, 20.0, &close), (vb - 20.0) / p.gipps.reaction_time_s, 1e-12);
  const LeaderView far{500.0, 30.0, 0.0};  // far away: the free term
  EXPECT_NEAR(car_following_accel_mps2(p, 20.0, &far), car_following_accel_mps2(p, 20.0, nullptr), 1e-12);
}

}  // namespace
}  // namespace entourage
