// The director's transport: moving an actor towards its slot, its lead on the desired speed,
// passing on the way, clearing zones and making way for actors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core_test_util.hpp"
#include "director/core/transport.hpp"
#include "director_test_util.hpp"

namespace entourage::director {
namespace {

using testing::at_trigger2;
using testing::lead_play;
using testing::vehicle;

// A role of the ego's (forward) direction that starts in `lane`: where and how fast matter only
// against vehicle types (ClearingSituation::types), which these tests give where they need them.
std::vector<Slot> role_starting_in(int lane) { return {{Direction::kForward, lane, 0.0, 0.0}}; }

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

// The ego in the right lane of two, at 2000 m and 25 m/s, with the director's defaults.
struct EgoInTheRightLaneOfTwo : ::testing::Test {
  DirectorConfig cfg;
  const Lanes lanes{2, 0};
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0, 0);
};

TEST_F(EgoInTheRightLaneOfTwo, AClearedVehicleAheadOfTheEgoThatCannotMakeItInTimeDrivesAtTheTopOfTheBand) {
  // Both lanes zones from 5 to 120 m ahead at the start, 10 s from now; vehicle 1 ends 20 m ahead
  // of the ego, in the ego's lane: it must be 107 m further ahead, 21.5 m/s faster over the 5 s
  // planned and 10.7 m/s even by the start: beyond the 8 m/s band in either lane.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 2255.0, 2370.0},
                                       {Direction::kForward, 1, 2255.0, 2370.0}};
  const std::vector<Slot> no_roles;
  const ObservedVehicle v = vehicle(1, 2020.0, 25.0);
  const auto top = clear_out(v, ClearingSituation{zones, 10.0, ego, 2250.0, no_roles, lanes, cfg});
  ASSERT_TRUE(top.has_value());
  EXPECT_DOUBLE_EQ(top->speed_mps, v.speed_mps + cfg.max_speed_offset_mps);
  EXPECT_EQ(top->lane, 0);
}

TEST_F(EgoInTheRightLaneOfTwo, NoClearedVehicleIsAskedAboveItsTypesTopSpeed) {
  // As above, but vehicle 1 is a truck, and trucks wish 95 km/h at most: the top of its band is
  // that, not its speed plus the band's 8 m/s (a truck at 127 km/h in the cut-in, stop 44). A car
  // of a type that may go faster still gets the whole band.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 2255.0, 2370.0},
                                       {Direction::kForward, 1, 2255.0, 2370.0}};
  const std::vector<Slot> no_roles;
  const double truck_top_mps = 95.0 / 3.6;
  const TypeTable types{{1.4, true, 160.0 / 3.6}, {0.6, true, truck_top_mps}};
  ObservedVehicle truck = vehicle(1, 2020.0, 25.0);
  truck.type_index = 1;
  const auto truck_out = clear_out(truck, ClearingSituation{zones, 10.0, ego, 2250.0, no_roles, lanes, cfg, {}, types});
  ASSERT_TRUE(truck_out.has_value());
  EXPECT_DOUBLE_EQ(truck_out->speed_mps, truck_top_mps);
  ObservedVehicle car = truck;
  car.type_index = 0;
  const auto car_out = clear_out(car, ClearingSituation{zones, 10.0, ego, 2250.0, no_roles, lanes, cfg, {}, types});
  ASSERT_TRUE(car_out.has_value());
  EXPECT_DOUBLE_EQ(car_out->speed_mps, car.speed_mps + cfg.max_speed_offset_mps);
  // The band never ends below the truck's present speed (above its type's top, it is not asked to
  // be faster still).
  truck.speed_mps = truck_top_mps + 1.0;
  const auto fast = clear_out(truck, ClearingSituation{zones, 10.0, ego, 2250.0, no_roles, lanes, cfg, {}, types});
  ASSERT_TRUE(fast.has_value());
  EXPECT_DOUBLE_EQ(fast->speed_mps, truck.speed_mps);
}

TEST_F(EgoInTheRightLaneOfTwo, TheEgosLeaderInAZoneMovesAheadInTheActorsLaneOnlyOutOfTheActorsWay) {
  // A cut-in 40 s from now (ego then at 3000 m): the ego's lane a zone from 3 to 60 m ahead, the
  // cutter's room in the left lane from 3008 to 3046 m. The ego's leader, 45 m ahead of it at its
  // speed, would stand in the zone: by its speed alone it stays in the queue the ego follows.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 3003.0, 3060.0},
                                       {Direction::kForward, 1, 3008.0, 3046.0}};
  const std::vector<Slot> roles = role_starting_in(1);
  const ObservedVehicle leader = vehicle(1, 2045.0, 25.0, 0);
  auto clear = [&](std::vector<ActorPlace> actors) {
    return clear_out(leader, ClearingSituation{zones, 40.0, ego, 3000.0, roles, lanes, cfg, std::move(actors)});
  };
  // No actor in the left lane yet: it changes there and is ahead of the cutter's room 5 s early.
  const auto moved = clear({});
  ASSERT_TRUE(moved.has_value());
  EXPECT_EQ(moved->lane, 1);
  EXPECT_NEAR(leader.s_m + moved->speed_mps * 35.0, 3046.0 + 2.25 + 5.0, 1e-9);
  // The cutter far behind it at its speed: out of its way all the same.
  EXPECT_EQ(clear({{1, 1800.0, 25.0}})->lane, 1);
  // The cutter ahead of it in that lane: it would have to get past the cutter; and the cutter
  // behind it but faster, reaching it before the start: in its way. It stays in its lane and is
  // sent ahead of the zone there.
  for (const ActorPlace& cutter : {ActorPlace{1, 2100.0, 25.0}, ActorPlace{1, 1950.0, 33.0}}) {
    const auto stays = clear({cutter});
    ASSERT_TRUE(stays.has_value());
    EXPECT_EQ(stays->lane, 0);
  }
}

TEST_F(EgoInTheRightLaneOfTwo, TheEgosLeaderIsNeverSentAheadOfAnActorThatStartsFasterThanItsTypeDrives) {
  // The cut-in above, the cutter to start at 27 m/s in the left lane. A car as the ego's leader
  // moves there, ahead of the cutter's room, as above. A truck, whose drivers wish 95 km/h
  // (26.4 m/s) at most, would be caught by the cutter: it stays in the ego's lane (a truck sent
  // ahead of the cutter held it back in 14 of the cut-in's 51 failures, stop 45). Nor with the
  // cutter to start at 26 m/s, within 1 m/s of the truck's top: the cutter's start speed rises with
  // the ego's (stop 50). With the cutter to start at 25 m/s the truck moves over as the car does.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 3003.0, 3060.0},
                                       {Direction::kForward, 1, 3008.0, 3046.0}};
  const TypeTable types{{1.4, true, 160.0 / 3.6}, {0.6, true, 95.0 / 3.6}};
  ObservedVehicle leader = vehicle(1, 2045.0, 25.0, 0);
  auto lane_of = [&](int type_index, double cutter_speed_mps) {
    leader.type_index = type_index;
    const std::vector<Slot> slots{{Direction::kForward, 1, 3016.0, cutter_speed_mps}};
    const auto c = clear_out(leader, ClearingSituation{zones, 40.0, ego, 3000.0, slots, lanes, cfg, {}, types});
    return c.has_value() ? c->lane : -1;
  };
  EXPECT_EQ(lane_of(0, 27.0), 1);
  EXPECT_EQ(lane_of(1, 27.0), 0);
  EXPECT_EQ(lane_of(1, 26.0), 0);
  EXPECT_EQ(lane_of(1, 25.0), 1);
}

TEST_F(EgoInTheRightLaneOfTwo, LateATruckTheEgoFollowsAtTheZonesEdgeMovesAheadOfACutterInPlace) {
  // A cut-in, the cutter to start at 27 m/s in the left lane 12 m ahead of the ego, the ego's lane
  // a zone from 3 to 60 m ahead of it. A truck (16.5 m, drivers wish 95 km/h at most) 60 m ahead
  // of the ego, which follows it at its speed, would stand in the zone by a few metres at the start,
  // and it cannot get ahead of it. 10 s before the start, with the cutter on its way to its place,
  // it moves over ahead of the cutter's room (the cutter leaves that lane when it cuts in): ten of
  // the cut-in's 41 failures on seeds 1-200 were such a truck in the zone with the cutter in place
  // (stop 46). Not 20 s before, nor when the ego closes on it, nor with the cutter still catching up
  // from behind.
  const TypeTable types{{1.4, true, 160.0 / 3.6}, {0.6, true, 95.0 / 3.6}};
  auto lane_of = [&](double time_left_s, double ego_speed_mps, double cutter_short_m) {
    const EgoObservation e = testing::ego_at(0, 2000.0, ego_speed_mps, 0);
    const double ego_then_m = 2000.0 + 25.0 * time_left_s;  // the estimate: at the truck's speed
    const std::vector<Slot> slots{{Direction::kForward, 1, ego_then_m + 12.0, 27.0}};
    const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, ego_then_m + 3.0, ego_then_m + 60.0},
                                         {Direction::kForward, 1, ego_then_m - 25.0, ego_then_m + 4.0},
                                         {Direction::kForward, 1, ego_then_m + 7.75, ego_then_m + 46.25}};
    const std::vector<ActorPlace> actors{{1, slots[0].s_m - 27.0 * time_left_s - cutter_short_m, 27.0}};
    ObservedVehicle truck = vehicle(1, 2060.0, 25.0, 0);
    truck.type_index = 1;
    truck.length_m = 16.5;
    const auto c = clear_out(truck, ClearingSituation{zones, time_left_s, e, ego_then_m, slots, lanes, cfg, actors, types});
    return c.has_value() ? c->lane : -1;
  };
  EXPECT_EQ(lane_of(10.0, 25.0, 0.0), 1);
  EXPECT_EQ(lane_of(20.0, 25.0, 0.0), 0);
  EXPECT_EQ(lane_of(10.0, 27.0, 0.0), 0);
  EXPECT_EQ(lane_of(10.0, 25.0, 30.0), 0);
}

TEST_F(EgoInTheRightLaneOfTwo, LateOnTheEgosLeaderMovesAheadInTheNextLaneByTheStartWhenItCannotBeThereEarly) {
  // 10 s before a cut-in (ego then at 2250 m): the ego's lane a zone from 3 to 60 m ahead, the
  // cutter's room in the left lane from 2258 to 2296 m. The ego's leader, 30 m ahead of it at its
  // speed, would stand in the zone. Ahead of the room 5 s early it would need 54.7 m/s; by the start
  // 27.3 m/s, within the band: it moves over and speeds up to that. (Kept in the ego's lane at the
  // top of the band behind the ego's own leaders, a car stood in the zone at the start: cut-in, seed 58.)
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 2253.0, 2310.0},
                                       {Direction::kForward, 1, 2258.0, 2296.0}};
  const std::vector<Slot> roles = role_starting_in(1);
  const ObservedVehicle leader = vehicle(1, 2030.0, 25.0, 0);
  const auto moved = clear_out(leader, ClearingSituation{zones, 10.0, ego, 2250.0, roles, lanes, cfg});
  ASSERT_TRUE(moved.has_value());
  EXPECT_EQ(moved->lane, 1);
  EXPECT_NEAR(leader.s_m + moved->speed_mps * 10.0, 2296.0 + 2.25 + 5.0, 1e-9);
}

TEST_F(EgoInTheRightLaneOfTwo, AVehicleInTheZoneBehindTheCutterFallsBackByTheStartWhenItCannotEarly) {
  // 14 s before a cut-in (ego then at 2350 m): the ego's lane a zone from 3 to 60 m ahead; in the
  // left lane a zone from 25 m behind the ego to 4 m ahead of it, then the cutter's room from
  // 2357.75 to 2394.25 m (cleared as one with it). A car 17 m behind the ego in the left lane, the
  // cutter 29 m ahead of it there, would stand in the zone: it can only fall back. Behind the zone
  // 5 s early it would need 37.2 m/s (the zone moves on with the ego), beyond the band; by the
  // start 23.9 m/s: it slows down rather than drive at the top of the band into the zone.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 2353.0, 2410.0},
                                       {Direction::kForward, 1, 2325.0, 2354.0},
                                       {Direction::kForward, 1, 2357.75, 2394.25}};
  const std::vector<Slot> roles = role_starting_in(1);
  const ObservedVehicle car = vehicle(1, 1983.0, 25.0, 1);
  const auto back = clear_out(car, ClearingSituation{zones, 14.0, ego, 2350.0, roles, lanes, cfg, {{1, 2012.0, 25.0}}});
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->lane, 1);
  EXPECT_NEAR(car.s_m + back->speed_mps * 14.0, 2325.0 - 2.25 - 5.0, 1e-9);
  EXPECT_LT(back->speed_mps, car.speed_mps);
}

TEST_F(EgoInTheRightLaneOfTwo, AVehicleNeverMovesOutOfAZoneIntoALaneWhereAnActorIsAlongsideIt) {
  // 20 s before a lead play's start (ego then at 2500 m): the ego's lane a zone from 3 to 37 m
  // ahead and the lead's room from 2535.75 to 2572.25 m. A car 51 m ahead of the ego would stand
  // in the room; the left lane is free of zones and roles. With the lead beside it there (14 m
  // behind it, waiting to move in where the car is), moving over would cut in on the lead: it is
  // sent ahead in its own lane instead. With the lead far behind, it moves over.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 2503.0, 2537.0},
                                       {Direction::kForward, 0, 2535.75, 2572.25}};
  const std::vector<Slot> roles = role_starting_in(0);
  const ObservedVehicle car = vehicle(1, 2051.0, 25.0, 0);
  auto clear = [&](std::vector<ActorPlace> actors) {
    return clear_out(car, ClearingSituation{zones, 20.0, ego, 2500.0, roles, lanes, cfg, std::move(actors)});
  };
  const auto beside = clear({{1, 2037.0, 25.0}});
  ASSERT_TRUE(beside.has_value());
  EXPECT_EQ(beside->lane, 0);
  EXPECT_GT(beside->speed_mps, car.speed_mps);
  const auto far = clear({{1, 1960.0, 25.0}});
  ASSERT_TRUE(far.has_value());
  EXPECT_EQ(far->lane, 1);
}

TEST_F(EgoInTheRightLaneOfTwo, AVehicleInAnActorsLaneIsClearedOnlyOnItsOwnSideOfTheActor) {
  // The cutter's room in the left lane from 3008 to 3046 m at the start, 40 s from now (ego then at
  // 3000 m, the ego's lane a zone from 3 to 60 m). A car in the left lane would stand in the room:
  // falling back behind it is the smaller change of speed (27.45 against 28.95 m/s).
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 3003.0, 3060.0},
                                       {Direction::kForward, 1, 3008.0, 3046.0}};
  const std::vector<Slot> roles = role_starting_in(1);
  const ObservedVehicle car = vehicle(1, 2040.0, 25.0, 1);
  auto clear = [&](std::vector<ActorPlace> actors) {
    return clear_out(car, ClearingSituation{zones, 40.0, ego, 3000.0, roles, lanes, cfg, std::move(actors)});
  };
  const double behind_mps = (3008.0 - 2.25 - 5.0 - 2040.0) / 35.0;
  const double ahead_mps = (3046.0 + 2.25 + 5.0 - 2040.0) / 35.0;
  ASSERT_TRUE(clear({}).has_value());
  EXPECT_NEAR(clear({})->speed_mps, behind_mps, 1e-9);
  // With the cutter behind it in that lane, falling back would take the cutter back with it: ahead.
  const auto ahead = clear({{1, 2010.0, 25.0}});
  ASSERT_TRUE(ahead.has_value());
  EXPECT_NEAR(ahead->speed_mps, ahead_mps, 1e-9);
  EXPECT_EQ(ahead->lane, 1);
  // With the cutter ahead of it, it stays behind; an actor in the other lane does not count.
  EXPECT_NEAR(clear({{1, 2070.0, 25.0}})->speed_mps, behind_mps, 1e-9);
  EXPECT_NEAR(clear({{0, 2010.0, 25.0}})->speed_mps, behind_mps, 1e-9);
}

// A cutter on its way: its slot in the left lane of two, 12 m ahead of the ego at the start, 40 s
// from now; the actor 100 m behind the ego in that lane, the ego in the right lane.
struct CutterOnItsWay : EgoInTheRightLaneOfTwo {
  const Slot slot{Direction::kForward, 1, 3012.0, 26.0};
  const ObservedVehicle actor = vehicle(1, 1900.0, 26.0, 1);
};

TEST_F(CutterOnItsWay, AnActorHeldUpPassesOnlyByALaneInWhichItIsNotHeldUpAsWell) {
  // A slower vehicle 50 m ahead of it in the left lane, the ego ahead of it in the right lane:
  // passing on the right would leave it behind the ego. It stays in the slot's lane.
  const std::vector<ObservedVehicle> world{actor, vehicle(2, 1950.0, 24.0, 1)};
  const TransportCommand stay = transport(slot, actor, 40.0, -1.0, 0.1, world, ego, lanes, cfg, cfg.transport_rate_mps2, 0.0);
  EXPECT_EQ(stay.lane, 1);
  // With the ego far ahead (beyond the passing horizon), the right lane is free: it passes there.
  const EgoObservation far_ego = testing::ego_at(0, 2600.0, 25.0, 0);
  const TransportCommand pass = transport(slot, actor, 40.0, -1.0, 0.1, world, far_ego, lanes, cfg, cfg.transport_rate_mps2, 0.0);
  EXPECT_EQ(pass.lane, 0);
}

TEST_F(CutterOnItsWay, AnActorAheadOfTheEgoDoesNotPassInTheEgosLane) {
  // The cutter 30 m ahead of the ego in the left lane, a slower car 60 m ahead of it there, the
  // right lane free but for the ego behind. Passing on the right would put the cutter in front of
  // the ego, where it would soon slow to its start's pace and hold the ego up: it stays.
  const ObservedVehicle ahead = vehicle(1, 2030.0, 26.0, 1);
  const std::vector<ObservedVehicle> world{ahead, vehicle(2, 2090.0, 23.0, 1)};
  const TransportCommand c = transport(slot, ahead, 40.0, -1.0, 0.1, world, ego, lanes, cfg, cfg.transport_rate_mps2, 0.0);
  EXPECT_EQ(c.lane, 1);
  // The same with its start in the ego's lane (a lead vehicle): that lane is its own, it passes.
  const Slot lead_slot{Direction::kForward, 0, 3060.0, 26.0};
  const ObservedVehicle lead = vehicle(1, 2030.0, 26.0, 0);
  const std::vector<ObservedVehicle> held{lead, vehicle(2, 2090.0, 23.0, 0)};
  EXPECT_EQ(transport(lead_slot, lead, 40.0, -1.0, 0.1, held, ego, lanes, cfg, cfg.transport_rate_mps2, 0.0).lane, 1);
}

TEST_F(CutterOnItsWay, AVehicleHoldingAnActorUpOnItsWayMakesWayToALaneClearOfTheZones) {
  // The ego's lane is a zone from 3 to 60 m ahead of it at the start (40 s from now, at 3000 m).
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 3003.0, 3060.0}};
  const std::vector<Slot> roles = role_starting_in(1);
  const ObservedVehicle slow = vehicle(2, 1950.0, 24.0, 1);  // ends 1910 + 1000 = 2910: behind the zone
  const ClearingSituation at{zones, 40.0, ego, 3000.0, roles, lanes, cfg};
  const auto way = make_way(slow, slot, actor, 27.0, -1, at);
  ASSERT_TRUE(way.has_value());
  EXPECT_EQ(way->lane, 0);
  EXPECT_EQ(way->speed_mps, kOwnDesiredSpeed_mps);
  // Not a vehicle it would move into a zone (it would end 40 m ahead of the ego in its lane) ...
  const ObservedVehicle into_zone = vehicle(3, 2020.0, 25.5, 1);
  EXPECT_FALSE(make_way(into_zone, slot, actor, 28.0, -1, at).has_value());
  // ... nor one as fast as the actor's command, one behind the actor, one beyond its horizon, or
  // one in another lane.
  EXPECT_FALSE(make_way(vehicle(4, 1950.0, 26.5, 1), slot, actor, 27.0, -1, at).has_value());
  EXPECT_FALSE(make_way(vehicle(5, 1880.0, 20.0, 1), slot, actor, 27.0, -1, at).has_value());
  EXPECT_FALSE(make_way(vehicle(6, 2200.0, 20.0, 1), slot, actor, 27.0, -1, at).has_value());
  EXPECT_FALSE(make_way(vehicle(7, 1950.0, 20.0, 0), slot, actor, 27.0, -1, at).has_value());
}

TEST_F(CutterOnItsWay, AVehicleNeverMakesWayIntoTheLaneTheActorPassesIn) {
  // The same slow vehicle ahead of the actor, the right lane clear of the zone where it will be.
  // An actor told to pass in the right lane, moving there, or in it already: the slow one keeps
  // its lane, or it would stand in front of the actor in the lane the actor passes in.
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, 3003.0, 3060.0}};
  const std::vector<Slot> roles = role_starting_in(1);
  const ObservedVehicle slow = vehicle(2, 1950.0, 24.0, 1);
  const ClearingSituation at{zones, 40.0, ego, 3000.0, roles, lanes, cfg};
  ASSERT_TRUE(make_way(slow, slot, actor, 27.0, 1, at).has_value());  // told to keep its lane
  EXPECT_FALSE(make_way(slow, slot, actor, 27.0, 0, at).has_value());  // told to pass on the right
  ObservedVehicle moving = actor;
  moving.target_lane = 0;
  EXPECT_FALSE(make_way(slow, slot, moving, 27.0, 1, at).has_value());
  ObservedVehicle beside = actor;
  beside.lane = 0;
  beside.target_lane = 0;
  EXPECT_FALSE(make_way(vehicle(3, 1950.0, 24.0, 1), slot, beside, 27.0, 0, at).has_value());
}

}  // namespace
}  // namespace entourage::director
