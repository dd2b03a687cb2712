// The meso speed update (services/meso/core/meso_model.hpp): it keeps an equilibrium, returns to
// it at comfortable rates, brakes harder only for a leader too close, never beyond the vehicle's
// limit except to stay out of a leader, and never drives into a leader.
#include <gtest/gtest.h>

#include "core/random.hpp"
#include "core_test_util.hpp"
#include "meso/core/meso_model.hpp"
#include "traffic/driver_draw.hpp"

namespace entourage::meso {
namespace {

constexpr double kDt = 0.1;

struct Case {
  ScenarioConfig sc = entourage::testing::minimal_scenario();
  Vehicle v;
  EquilibriumSpeed eq;
  Case(double speed_mps, double v0_mps) {
    Random rng(7);
    const DriverParams d = draw_driver(sc.vehicle_types[0], v0_mps, 7, rng);
    v = make_vehicle(1, 0, sc.vehicle_types[0], Direction::kForward, 0, 1000.0, speed_mps, d);
    eq = EquilibriumSpeed(v.driver.car_following);
  }
  const IdmParams& p() const { return v.driver.car_following.idm; }
  MesoSpeed next(const Ahead& a) const { return next_speed(v, eq, a, p().desired_speed_mps, PlanHorizon{kDt, 1}); }
  // The gap at which this driver's equilibrium speed is `speed_mps` (bisection on the table).
  double equilibrium_gap(double speed_mps) const {
    double lo = 0.0;
    double hi = eq.max_gap_m();
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (eq.at(mid) < speed_mps ? lo : hi) = mid;
    }
    return hi;
  }
};

TEST(MesoModel, KeepsAnEquilibrium) {
  Case c(25.0, 33.0);
  const double gap = c.equilibrium_gap(25.0);
  const MesoSpeed s = c.next({gap, 25.0});
  EXPECT_NEAR(s.speed_mps, 25.0, 0.05);
  EXPECT_FALSE(s.emergency);
}

TEST(MesoModel, FreeRoadAcceleratesAtMostAtTheDriversRate) {
  Case c(20.0, 33.0);
  const MesoSpeed s = c.next({});
  EXPECT_GT(s.speed_mps, 20.0);
  EXPECT_LE(s.speed_mps - 20.0, c.p().max_accel_mps2 * kDt + 1e-9);
}

TEST(MesoModel, ACloseButSafeLeaderIsApproachedAtComfortableDeceleration) {
  // Half the equilibrium gap behind a leader at the same speed: too close for equilibrium but far
  // enough to brake comfortably, so no harder than b (the old update braked at b_max at once).
  Case c(28.0, 33.0);
  const double gap = 0.5 * c.equilibrium_gap(28.0);
  const MesoSpeed s = c.next({gap, 28.0});
  EXPECT_LT(s.speed_mps, 28.0);
  EXPECT_GE(s.speed_mps, 28.0 - c.p().comfort_decel_mps2 * kDt - 1e-9);
  EXPECT_FALSE(s.emergency);
}

TEST(MesoModel, AVehicleThatJustEnteredCloseBehindDoesNotStopDead) {
  // 2.5 m behind a leader at the same speed (a vehicle that changed lanes in front of a newborn):
  // it brakes hard, but the leader keeps moving, so it need not stop within a step.
  Case c(23.7, 33.0);
  const MesoSpeed s = c.next({2.5, 23.4});
  EXPECT_GE(s.speed_mps, 23.7 - c.v.driver.max_decel_mps2 * kDt - 1e-9);
  EXPECT_FALSE(s.emergency);
}

TEST(MesoModel, ALeaderTooCloseToBrakeForComfortablyMeansBrakingUpToTheLimit) {
  Case c(30.0, 33.0);
  const MesoSpeed s = c.next({20.0, 10.0});
  EXPECT_NEAR(s.speed_mps, 30.0 - c.v.driver.max_decel_mps2 * kDt, 1e-9);
}

TEST(MesoModel, NeverIntoTheLeaderEvenIfItBrakesAtTheFrictionLimit) {
  Case c(30.0, 33.0);
  for (double gap : {0.6, 1.0, 2.0, 3.0}) {
    const double leader = 5.0;
    const MesoSpeed s = c.next({gap, leader});
    const double leader_low = std::max(0.0, leader - MesoModelParams{}.leader_brake_limit_mps2 * kDt);
    EXPECT_LE(s.speed_mps * kDt, gap - MesoModelParams{}.floor_gap_m + leader_low * kDt + 1e-9) << gap;
    EXPECT_TRUE(s.emergency) << gap;
  }
  EXPECT_EQ(c.next({0.2, 0.0}).speed_mps, 0.0);
}

// A plan over a whole update period (10 steps of 0.1 s), integrated as the core integrates it: its
// steps never carry the vehicle beyond the floor gap behind a leader that brakes at the friction
// limit from the first step, whether it slows on a ramp or has to stop short of it.
TEST(MesoModel, APlanOverAPeriodNeverReachesALeaderThatBrakesAtTheFrictionLimit) {
  const PlanHorizon period{kDt, 10};
  const MesoModelParams m;
  for (double speed : {5.0, 15.0, 30.0}) {
    for (double leader : {0.0, 5.0, 20.0}) {
      for (double gap : {1.0, 5.0, 15.0, 40.0}) {
        Case c(speed, 33.0);
        const MesoSpeed s = next_speed(c.v, c.eq, {gap, leader}, c.p().desired_speed_mps, period, m);
        double v = speed;
        double vl = leader;
        double x = 0.0;
        double xl = gap;
        for (int i = 0; i < period.steps; ++i) {
          v = std::max(0.0, v + s.accel_mps2 * kDt);
          vl = std::max(0.0, vl - m.leader_brake_limit_mps2 * kDt);
          x += v * kDt;
          xl += vl * kDt;
          EXPECT_LE(x, xl - m.floor_gap_m + 1e-9) << speed << " " << leader << " " << gap << " step " << i;
        }
      }
    }
  }
}

// Without a leader, a plan is a ramp towards the desired speed at no more than the driver's rate.
TEST(MesoModel, APlanIsARampAtTheDriversRate) {
  Case c(20.0, 33.0);
  const MesoSpeed s = next_speed(c.v, c.eq, {}, c.p().desired_speed_mps, PlanHorizon{kDt, 10});
  EXPECT_NEAR(s.accel_mps2, c.p().max_accel_mps2, 1e-9);
  EXPECT_NEAR(s.speed_mps, 20.0 + c.p().max_accel_mps2 * 1.0, 1e-9);
}

TEST(MesoModel, AStandingObstacleIsBrakedForOnlyWhenComfortableBrakingNoLongerSuffices) {
  // A lane's end, and an oncoming overtaker expected back in its lane: not vehicles to follow.
  Case c(25.0, 33.0);
  const double stopping_m = 25.0 * 25.0 / (2.0 * c.p().comfort_decel_mps2) + c.p().min_gap_m;
  for (const Obstacle obstacle : {Obstacle::kLaneEnd, Obstacle::kOncoming}) {
    const Ahead far{stopping_m + 10.0, 0.0, 0.0, obstacle};
    const Ahead near{stopping_m - 10.0, 0.0, 0.0, obstacle};
    const Ahead close{30.0, 0.0, 0.0, obstacle};
    EXPECT_GE(c.next(far).speed_mps, 25.0 - 1e-9);
    EXPECT_LT(c.next(near).speed_mps, 25.0);
    EXPECT_NEAR(c.next(close).speed_mps, 25.0 - c.v.driver.max_decel_mps2 * kDt, 1e-9);
  }
}

TEST(MesoModel, ClosingInTooFastItBrakesAsItsOwnModelDoes) {
  // 35 m/s, 70 m behind a vehicle at 26 m/s: its equilibrium at that gap is above its speed and it
  // could still brake comfortably to the leader's bumper, but its car-following model brakes hard
  // (the approach rate): planned over a second, meso brakes as hard. Far behind (200 m) the model
  // brakes less than comfortably and the relaxation alone decides, as before.
  Case c(35.0, 40.0);
  const double dt = 1.0;
  auto plan = [&](double gap_m) { return next_speed(c.v, c.eq, {gap_m, 26.0}, 40.0, PlanHorizon{kDt, 10}); };
  const LeaderView leader{70.0, 26.0, 0.0};
  const double model = car_following_accel_mps2(c.v.driver.car_following, 35.0, &leader);
  ASSERT_LT(model, -c.p().comfort_decel_mps2);
  EXPECT_NEAR(plan(70.0).accel_mps2, std::max(model, -c.v.driver.max_decel_mps2), 1e-9);
  EXPECT_NEAR(plan(70.0).speed_mps, 35.0 + std::max(model, -c.v.driver.max_decel_mps2) * dt, 1e-9);
  const LeaderView far{200.0, 26.0, 0.0};
  ASSERT_GT(car_following_accel_mps2(c.v.driver.car_following, 35.0, &far), -c.p().comfort_decel_mps2);
  EXPECT_GE(plan(200.0).accel_mps2, -c.p().comfort_decel_mps2 - 1e-9);
}

}  // namespace
}  // namespace entourage::meso
