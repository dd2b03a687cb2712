// The director's transport: moving an actor towards its slot, its lead on the desired speed,
// clearing a zone, letting a waiting vehicle in. The same with the ego in the right lane of two
// (the ego's leader, actors alongside, passing on the way, making way):
// director_two_lanes_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core_test_util.hpp"
#include "director/core/clearing.hpp"
#include "director/core/transport.hpp"
#include "director_test_util.hpp"

namespace entourage::director {
namespace {

using testing::at_trigger2;
using testing::lead_play;
using testing::role_starting_in;
using testing::vehicle;

// Drives a plan step by step at its rate: to the cruise speed, cruise, and the final change once
// it is due; the distance covered and the speed at the end.
struct Driven {
  double distance_m = 0.0;
  double speed_mps = 0.0;
};
Driven drive_plan(const SpeedPlan& plan, double v0, double vf, double time_s, double rate_mps2) {
  const double dt = 1e-3;
  Driven d{0.0, v0};
  for (double t = 0.0; t < time_s - 0.5 * dt; t += dt) {
    const double target = time_s - t <= plan.final_change_s ? vf : plan.cruise_mps;
    const double v = std::clamp(target, d.speed_mps - rate_mps2 * dt, d.speed_mps + rate_mps2 * dt);
    d.distance_m += 0.5 * (d.speed_mps + v) * dt;
    d.speed_mps = v;
  }
  return d;
}

TEST(PlanSpeed, ATrapezoidCoversTheDistanceAndEndsAtTheFinalSpeedWhenTheBandAllows) {
  const SpeedBand band{10.0, 40.0};
  // Slower than both ends, between them, faster than both.
  for (const double distance : {520.0, 600.0, 680.0}) {
    const SpeedPlan plan = plan_speed(28.0, 22.0, 24.0, distance, band, 0.7);
    ASSERT_TRUE(plan.feasible()) << distance;
    EXPECT_NEAR(plan.final_change_s, std::abs(plan.cruise_mps - 22.0) / 0.7, 1e-9);
    const Driven d = drive_plan(plan, 28.0, 22.0, 24.0, 0.7);
    EXPECT_NEAR(d.distance_m, distance, 0.1) << distance;
    EXPECT_NEAR(d.speed_mps, 22.0, 0.01);
  }
}

TEST(PlanSpeed, WhereTheBandOrTheRateCannotCoverTheDistanceThePlanSaysByHowMuchItMisses) {
  // The stopper of the stopped-vehicle play when the ego sped up late (stop 37, seed 36): from
  // 27.9 m/s, 742 m in 24 s to arrive at 22.2 m/s. The band (the start speed + 8 m/s) caps the
  // cruise at 30.2 m/s; without the cap the rate alone still leaves it short.
  const SpeedPlan capped = plan_speed(27.9, 22.2, 24.0, 742.0, SpeedBand{14.2, 30.2}, 0.84);
  EXPECT_DOUBLE_EQ(capped.cruise_mps, 30.2);
  EXPECT_NEAR(capped.shortfall_m, 742.0 - drive_plan(capped, 27.9, 22.2, 24.0, 0.84).distance_m, 0.1);
  EXPECT_GT(capped.shortfall_m, 40.0);
  const SpeedPlan by_rate = plan_speed(27.9, 22.2, 24.0, 742.0, SpeedBand{14.2, 50.0}, 0.84);
  EXPECT_LT(by_rate.cruise_mps, 50.0);
  EXPECT_NEAR(by_rate.shortfall_m, 742.0 - drive_plan(by_rate, 27.9, 22.2, 24.0, 0.84).distance_m, 0.1);
  EXPECT_GT(by_rate.shortfall_m, 20.0);
  EXPECT_LT(by_rate.shortfall_m, capped.shortfall_m);
  // Too fast and too close: it misses the other way (arrives ahead of the slot).
  EXPECT_LT(plan_speed(30.0, 22.0, 20.0, 300.0, SpeedBand{14.0, 38.0}, 0.7).shortfall_m, 0.0);
}

TEST(Transport, AnActorTrackingItsCommandReachesTheSlotWithinAMetreAndTheSlotSpeed) {
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{2, 0})[0];
  // 840 m in 40 s, from 20 m/s to the ego's 25: cruise near 20, speed up at the end.
  ObservedVehicle actor = vehicle(1, 2200.0, 20.0);
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const double dt = 0.1;
  double cmd = -1.0;
  double max_accel = 0.0;
  for (double t_left = 40.0; t_left > 0.0; t_left -= dt) {
    const TransportCommand c = transport(slot, actor, t_left, cmd, dt, {}, ego, Lanes{2, 0}, cfg, cfg.transport_rate_mps2, 0.0);
    cmd = c.speed_mps;
    // A driver reaching its desired speed with a 2 s lag, at most 1.5 m/s^2.
    const double a = std::clamp((cmd - actor.speed_mps) / 2.0, -1.5, 1.5);
    max_accel = std::max(max_accel, std::abs(a));
    actor.speed_mps += a * dt;
    actor.s_m += actor.speed_mps * dt;
  }
  EXPECT_NEAR(actor.s_m, slot.s_m, 3.0);
  EXPECT_NEAR(actor.speed_mps, slot.speed_mps, 1.0);
  EXPECT_LE(max_accel, 1.0 + 1e-9);
  // Too far ahead and too fast to make it: the plan says by how much it will miss.
  const TransportCommand miss =
      transport(slot, vehicle(2, 2300.0, 30.0), 40.0, -1.0, dt, {}, ego, Lanes{2, 0}, cfg, cfg.transport_rate_mps2, 0.0);
  EXPECT_LT(miss.position_error_m, -20.0);
}

TEST(Transport, NearTheEgoTheDesiredSpeedFallsAsFastAsTheEgoBrakesUpToAComfortableRate) {
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{2, 0})[0];
  // 80 m ahead of the ego and fast: the plan wants it much slower (960 m in 40 s).
  const double dt = 0.1;
  const auto fall_per_step = [&](double ego_accel_mps2, double actor_s_m) {
    EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
    ego.accel_mps2 = ego_accel_mps2;
    const TransportCommand c =
        transport(slot, vehicle(2, actor_s_m, 30.0), 40.0, 30.0, dt, {}, ego, Lanes{2, 0}, cfg, cfg.transport_rate_mps2, 0.0);
    return 30.0 - c.speed_mps;
  };
  EXPECT_NEAR(fall_per_step(0.0, 2080.0), kCommandRate_mps2 * dt, 1e-9);   // a steady ego
  EXPECT_NEAR(fall_per_step(0.5, 2080.0), kCommandRate_mps2 * dt, 1e-9);   // one speeding up
  EXPECT_NEAR(fall_per_step(-0.6, 2080.0), kCommandRate_mps2 * dt, 1e-9);  // braking gently
  EXPECT_NEAR(fall_per_step(-1.5, 2080.0), 1.5 * dt, 1e-9);                // braking harder: as fast
  EXPECT_NEAR(fall_per_step(-6.0, 2080.0), kCommandFallWithEgoMax_mps2 * dt, 1e-9);  // hard: a comfortable rate
  // Further from the ego than kCommandFallWithEgoWithin_m (behind it or ahead): its own pace.
  EXPECT_NEAR(fall_per_step(-1.5, 2000.0 + kCommandFallWithEgoWithin_m + 1.0), kCommandRate_mps2 * dt, 1e-9);
  EXPECT_NEAR(fall_per_step(-1.5, 2000.0 - kCommandFallWithEgoWithin_m - 1.0), kCommandRate_mps2 * dt, 1e-9);
  // It rises at the command rate whatever the ego does.
  EgoObservation braking = testing::ego_at(0, 2000.0, 25.0);
  braking.accel_mps2 = -3.0;
  const TransportCommand up =
      transport(slot, vehicle(3, 1200.0, 20.0), 40.0, 20.0, dt, {}, braking, Lanes{2, 0}, cfg, cfg.transport_rate_mps2, 0.0);
  EXPECT_NEAR(up.speed_mps - 20.0, kCommandRate_mps2 * dt, 1e-9);
}

TEST(Transport, AnActorToSpeedUpIsGivenTheDesiredSpeedAtWhichItsFreeRoadAccelerationIsThePlansRate) {
  // IDM's free road: a (1 - (v / v0)^4); with v0 the drive speed, that is the plan's rate.
  const double a = 1.4;
  const double rate = 0.7;
  const double v = 25.0;
  const double drive = drive_speed_mps(27.0, v, rate, a);
  EXPECT_NEAR(a * (1.0 - std::pow(v / drive, 4.0)), rate, 1e-9);
  EXPECT_GT(drive, 27.0);
  // At or above the speed it should drive at, or with an unknown type: that speed itself.
  EXPECT_DOUBLE_EQ(drive_speed_mps(25.0, 25.0, rate, a), 25.0);
  EXPECT_DOUBLE_EQ(drive_speed_mps(24.0, 25.0, rate, a), 24.0);
  EXPECT_DOUBLE_EQ(drive_speed_mps(27.0, v, rate, 0.0), 27.0);
  // Close below it the plain speed is already enough: never less than it.
  EXPECT_DOUBLE_EQ(drive_speed_mps(40.0, v, rate, a), 40.0);
}

TEST(Transport, AnActorNearerAheadOfTheEgoThanItsStartNeverDrivesSlowerThanItsStartSpeedRelativeToTheEgo) {
  // The lead, to start 40 m ahead at the ego's speed, is 20 m ahead of an ego at 20 m/s: it keeps
  // at least the ego's speed and opens the gap (20 m over 10 s: 2 m/s faster).
  EXPECT_DOUBLE_EQ(ego_pace_floor_mps(20.0, 40.0, 20.0, 0.0), 22.0);
  // Nearly there, it opens the last metres slowly; the gap is never closed by the floor.
  EXPECT_NEAR(ego_pace_floor_mps(39.0, 40.0, 20.0, 0.0), 20.1, 1e-12);
  // Far nearer than its start: at most kOpenToStartMax_mps faster than its start speed.
  EXPECT_DOUBLE_EQ(ego_pace_floor_mps(5.0, 60.0, 20.0, -2.0), 18.0 + kOpenToStartMax_mps);
  // Beyond its start (the plan brings it back) or not ahead of the ego: no floor.
  EXPECT_LT(ego_pace_floor_mps(45.0, 40.0, 20.0, 0.0), 0.0);
  EXPECT_LT(ego_pace_floor_mps(-10.0, 40.0, 20.0, 0.0), 0.0);
  // A start slower than a standing ego: no negative speed.
  EXPECT_NEAR(ego_pace_floor_mps(39.0, 40.0, 0.0, -5.0), 0.1, 1e-12);
}

TEST(Transport, AnActorWithAnAbsoluteStartSpeedWithinItsToleranceOfItsStartNeverDrivesSlowerThanThatSpeed) {
  // A truck to start 45 m ahead at 16.7 m/s (tolerance 15 m): 55 m ahead it is there already and
  // keeps its start speed whatever the ego does; nearer, it opens the gap as a relative role does.
  EXPECT_DOUBLE_EQ(start_speed_floor_mps(55.0, 45.0, 15.0, 16.7), 16.7);
  EXPECT_DOUBLE_EQ(start_speed_floor_mps(60.0, 45.0, 15.0, 16.7), 16.7);
  EXPECT_DOUBLE_EQ(start_speed_floor_mps(35.0, 45.0, 15.0, 16.7), 17.7);
  EXPECT_DOUBLE_EQ(start_speed_floor_mps(5.0, 45.0, 15.0, 16.7), 16.7 + kOpenToStartMax_mps);
  // Further than its tolerance (the plan brings it back) or not ahead of the ego: no floor.
  EXPECT_LT(start_speed_floor_mps(61.0, 45.0, 15.0, 16.7), 0.0);
  EXPECT_LT(start_speed_floor_mps(-3.0, 45.0, 15.0, 16.7), 0.0);
}

TEST(Transport, AVehicleThatWouldStandInAClearZoneIsSentToTheNextLaneOrOutOfTheZone) {
  PlayConfig play = lead_play();
  play.clear = {{0, 5.0, 40.0}};
  DirectorConfig cfg;
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0, 1);  // beside, in the left lane
  // At 25 m/s for 40 s, vehicle 1 ends 20 m ahead of the ego's handover position: in the zone.
  const ObservedVehicle v = vehicle(1, 2020.0, 25.0);
  auto clear = [&](const ObservedVehicle& x, const PlayConfig& p, const Lanes& lanes, const EgoObservation& e) {
    const std::vector<ZoneAtStart> zones = zones_of(p, Direction::kForward, 0, 3000.0, lanes);
    const std::vector<Slot> roles = role_starting_in(0);
    return clear_out(x, ClearingSituation{zones, 40.0, e, 3000.0, roles, lanes, cfg});
  };
  const auto two = clear(v, play, Lanes{2, 0}, ego);
  ASSERT_TRUE(two.has_value());
  EXPECT_EQ(two->lane, 1);
  // Both lanes zones: out by its speed, ahead of the zone or behind it at the start, whichever
  // is the smaller change: behind.
  PlayConfig both = play;
  both.clear.push_back({1, 5.0, 40.0});
  const auto out = clear(v, both, Lanes{2, 0}, ego);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->lane, 0);
  EXPECT_NEAR(v.s_m + out->speed_mps * 35.0, 3005.0 - 2.25 - 5.0, 1e-9);  // out 5 s early
  // With the ego behind it in its lane it cannot fall behind the ego: ahead of the zone, and in
  // the next lane, where the ego does not close up behind it.
  const auto ahead = clear(v, both, Lanes{2, 0}, testing::ego_at(0, 2000.0, 25.0, 0));
  ASSERT_TRUE(ahead.has_value());
  EXPECT_EQ(ahead->lane, 1);
  EXPECT_NEAR(v.s_m + ahead->speed_mps * 35.0, 3040.0 + 2.25 + 5.0, 1e-9);
  // On one lane it would have to overtake or be overtaken: left to its own driving.
  EXPECT_FALSE(clear(v, play, Lanes{1, 1}, ego).has_value());
  EXPECT_FALSE(clear(vehicle(2, 2500.0, 25.0), play, Lanes{2, 0}, ego).has_value());
}

TEST(Transport, TheVehicleJustBehindInTheTargetLaneLetsAWaitingVehicleInUnlessTheEgoIsThere) {
  const ObservedVehicle waiting = vehicle(1, 1000.0, 25.0, 0);
  const EgoObservation ego = testing::ego_at(0, 800.0, 25.0, 0);
  // Beside it (overlapping) and further back: the nearer one lets it in; one ahead does not.
  const std::vector<ObservedVehicle> world{waiting, vehicle(2, 998.0, 27.0, 1), vehicle(3, 960.0, 27.0, 1),
                                           vehicle(4, 1003.0, 27.0, 1)};
  const ObservedVehicle* f = follower_to_let_in(waiting, 1, world, ego);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->id, 2U);
  // Too far behind (more than kLetInReach_s at its speed from the waiting one's rear): nobody.
  const std::vector<ObservedVehicle> far{waiting, vehicle(3, 1000.0 - 4.5 - kLetInReach_s * 27.0 - 1.0, 27.0, 1)};
  EXPECT_EQ(follower_to_let_in(waiting, 1, far, ego), nullptr);
  // The ego just behind it in that lane: the ego is not asked, and nobody behind the ego either.
  EXPECT_EQ(follower_to_let_in(waiting, 1, {waiting, vehicle(3, 960.0, 27.0, 1)}, testing::ego_at(0, 985.0, 25.0, 1)),
            nullptr);
}

// One that would let another in holds an actor up by holding back when it is ahead of the actor in
// the lane of the actor's start, the actor still behind that start, within kHoldsUpHorizon_s of it
// (beyond the start too), and the hold is below the actor's command by kHoldsUp_mps (cut-in, seed
// 243, stop 68).
TEST(Transport, HoldingBackToLetAnotherInHoldsUpAnActorBehindItOnItsWayToItsStart) {
  const Slot start{Direction::kForward, 1, 2012.0, 26.4};
  const ObservedVehicle actor = vehicle(7, 1950.0, 25.0, 1);
  const double cmd_mps = 30.0;
  const ObservedVehicle follower = vehicle(9, 2092.0, 26.0, 1);  // 80 m beyond the start
  EXPECT_TRUE(held_back_holds_up(follower, 23.0, start, actor, cmd_mps));
  // Not below the command by kHoldsUp_mps.
  EXPECT_FALSE(held_back_holds_up(follower, cmd_mps - kHoldsUp_mps, start, actor, cmd_mps));
  // Beyond kHoldsUpHorizon_s at the command.
  EXPECT_FALSE(held_back_holds_up(vehicle(9, 1950.0 + cmd_mps * kHoldsUpHorizon_s + 1.0, 26.0, 1), 23.0, start, actor,
                                  cmd_mps));
  // Behind the actor, or in another lane.
  EXPECT_FALSE(held_back_holds_up(vehicle(9, 1940.0, 26.0, 1), 23.0, start, actor, cmd_mps));
  EXPECT_FALSE(held_back_holds_up(vehicle(9, 2092.0, 26.0, 0), 23.0, start, actor, cmd_mps));
  // The actor beyond its start already, or not yet in its start's lane.
  EXPECT_FALSE(held_back_holds_up(follower, 23.0, start, vehicle(7, 2020.0, 25.0, 1), cmd_mps));
  EXPECT_FALSE(held_back_holds_up(follower, 23.0, start, vehicle(7, 1950.0, 25.0, 0), cmd_mps));
}

TEST(Transport, BesideAStandingWaitingVehicleTheOneBehindLetsItIn) {
  // Waiting at a standstill, with a queue standing in the target lane: vehicle 2 beside it, 2 m
  // behind its centre, holding back below its speed would stand beside it for good (traced: a lead
  // play's whole freeway stood for two minutes behind such a pair). Vehicle 3, queued 4.5 m behind
  // it, lets it in; vehicle 2 drives on.
  const ObservedVehicle waiting = vehicle(1, 1000.0, 0.0, 0);
  const EgoObservation ego = testing::ego_at(0, 900.0, 0.0, 0);
  const std::vector<ObservedVehicle> queue{waiting, vehicle(2, 998.0, 0.0, 1), vehicle(3, 991.0, 0.0, 1)};
  const ObservedVehicle* f = follower_to_let_in(waiting, 1, queue, ego);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->id, 3U);
  // Moving at more than kLetIn_mps, the one beside falls behind by holding back: it lets it in.
  ObservedVehicle moving = waiting;
  moving.speed_mps = 5.0;
  const ObservedVehicle* g = follower_to_let_in(moving, 1, {moving, vehicle(2, 998.0, 5.0, 1)}, ego);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->id, 2U);
}

TEST(Transport, AVehicleAskedToChangeLanesKeepsThatRequestWhileItWaitsAndForGoodOnceItMoves) {
  const LaneRequest asked{1, 10.0};  // into lane 1, asked at 10 s
  ObservedVehicle waiting = vehicle(5, 2000.0, 25.0, 0);
  waiting.indicator = 1;
  // Waiting in its lane: another rule's lane (its own, or the other side) is refused for
  // kHoldLaneRequest_s; then the new one is taken.
  EXPECT_TRUE(keeps_lane_request(waiting, asked, 0, 10.0 + 0.5 * kHoldLaneRequest_s));
  EXPECT_TRUE(keeps_lane_request(waiting, asked, 2, 10.0 + 0.5 * kHoldLaneRequest_s));
  EXPECT_FALSE(keeps_lane_request(waiting, asked, 0, 10.0 + kHoldLaneRequest_s + 0.1));
  // The same lane asked again (at another speed) is no conflict.
  EXPECT_FALSE(keeps_lane_request(waiting, asked, 1, 11.0));
  // Moving over: never reversed, however long it has waited.
  ObservedVehicle moving = waiting;
  moving.target_lane = 1;
  EXPECT_TRUE(keeps_lane_request(moving, asked, 0, 10.0 + 10.0 * kHoldLaneRequest_s));
  // There: the request is done, and the next may move it again.
  const ObservedVehicle there = vehicle(5, 2000.0, 25.0, 1);
  EXPECT_FALSE(keeps_lane_request(there, asked, 0, 11.0));
  EXPECT_FALSE(keeps_lane_request(waiting, LaneRequest{}, 0, 11.0));  // never asked
}

TEST(Transport, ZonesOfALaneTooCloseToStandBetweenAreClearedAsOne) {
  const ZoneAtStart a{Direction::kForward, 1, 100.0, 120.0};
  const ZoneAtStart b{Direction::kForward, 1, 130.0, 160.0};  // 10 m beyond a: too close
  const ZoneAtStart c{Direction::kForward, 1, 200.0, 220.0};  // 40 m beyond b: room between
  const ZoneAtStart other_lane{Direction::kForward, 0, 118.0, 300.0};
  const std::vector<ZoneAtStart> zones{a, b, c, other_lane};
  const ZoneAtStart j = joined_zone(a, zones, 14.5);
  EXPECT_DOUBLE_EQ(j.from_s_m, 100.0);
  EXPECT_DOUBLE_EQ(j.to_s_m, 160.0);
  EXPECT_EQ(j.lane, 1);
  EXPECT_DOUBLE_EQ(joined_zone(c, zones, 14.5).to_s_m, 220.0);
  EXPECT_DOUBLE_EQ(joined_zone(c, zones, 14.5).from_s_m, 200.0);
}

}  // namespace
}  // namespace entourage::director
