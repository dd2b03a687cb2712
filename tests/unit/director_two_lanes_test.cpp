// The director's transport and zone clearing with the ego in the right lane of two: where a
// cleared vehicle goes (the ego's leader into an actor's lane, early or late, never alongside an
// actor, never past one), how fast, and an actor passing on its way or made way for.
#include <gtest/gtest.h>

#include <vector>

#include "core_test_util.hpp"
#include "director/core/clearing.hpp"
#include "director/core/transport.hpp"
#include "director_test_util.hpp"

namespace entourage::director {
namespace {

using testing::role_starting_in;
using testing::vehicle;

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
  // and it cannot get ahead of it. 5 s before the start, with the cutter on its way to its place,
  // it moves over ahead of the cutter's room (the cutter leaves that lane when it cuts in): ten of
  // the cut-in's 41 failures on seeds 1-200 were such a truck in the zone with the cutter in place
  // (stop 46). Not 10 s before (since stop 54: the ego, no longer held up, sped up in the time left,
  // and the cutter, behind the truck, could not follow), nor when the ego closes on it, nor with the
  // cutter still catching up from behind.
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
  EXPECT_EQ(lane_of(5.0, 25.0, 0.0), 1);
  EXPECT_EQ(lane_of(10.0, 25.0, 0.0), 0);
  EXPECT_EQ(lane_of(5.0, 27.0, 0.0), 0);
  EXPECT_EQ(lane_of(5.0, 25.0, 30.0), 0);
}

TEST_F(EgoInTheRightLaneOfTwo, LateATruckAtItsTopSpeedAheadOfTheCuttersRoomMovesOverWithNoMarginOnTop) {
  // Cut-in seed 259 (stop 54): 5 s before the start, the cutter to start at 27.8 m/s in the left
  // lane 12 m ahead of the ego, its room there reaching 35 m beyond its start; the ego follows a
  // truck at the truck type's top speed (95 km/h), 58.5 m ahead, whose rear will be 3 m beyond the
  // room at the start. At its present speed it is ahead of the room: it moves over and keeps that
  // speed (left to its own desired speed, a truck slowed in front of the cutter: seed 51). Asked for
  // the 5 m margin of the other ways on top, it would have needed 0.4 m/s above its type's top
  // speed, stayed in the zone and failed the play.
  const double top_mps = 95.0 / 3.6;
  const TypeTable types{{1.4, true, 160.0 / 3.6}, {0.6, true, top_mps}};
  const double t = 5.0;
  const EgoObservation e = testing::ego_at(0, 2000.0, top_mps, 0);
  const double ego_then_m = 2000.0 + top_mps * t;
  const Slot slot{Direction::kForward, 1, ego_then_m + 12.0, 27.8};
  const std::vector<ZoneAtStart> zones{{Direction::kForward, 0, ego_then_m + 3.0, ego_then_m + 60.0},
                                       {Direction::kForward, 1, ego_then_m - 25.0, ego_then_m + 4.0},
                                       slot_zones({slot}, {4.5}, Direction::kForward)[0]};
  ASSERT_NEAR(zones[2].to_s_m, slot.s_m + 35.05, 1e-9);
  // The cutter 15 m ahead of the ego at 24 m/s: 8 m short of its start at that speed.
  const std::vector<ActorPlace> actors{{1, 2015.0, 24.0}};
  ObservedVehicle truck = vehicle(1, 2000.0 + 58.5, top_mps, 0);
  truck.type_index = 1;
  truck.length_m = 16.5;
  const std::vector<Slot> slots{slot};
  const ClearingSituation at{zones, t, e, ego_then_m, slots, lanes, cfg, actors, types};
  const auto moved = clear_out(truck, at);
  ASSERT_TRUE(moved.has_value());
  EXPECT_EQ(moved->lane, 1);
  EXPECT_DOUBLE_EQ(moved->speed_mps, top_mps);
  // Its rear 1 m inside the room at the start: it stays (asked for its top speed in its lane).
  truck.s_m -= 4.0;
  const auto stays = clear_out(truck, at);
  ASSERT_TRUE(stays.has_value());
  EXPECT_EQ(stays->lane, 0);
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

TEST_F(EgoInTheRightLaneOfTwo, AVehicleMovesBesideAnActorOnlyToSwapLanesWithItWhenItCannotGetOutBySpeed) {
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
  // The lead beside it in place, waiting to move into the car's lane, its start's
  // (lane_waited_for): the car still gets ahead of the room by its speed first, which holds nobody
  // back. A truck at its type's top speed cannot: the two swap lanes, the lead letting it in
  // (PlayRun::let_in). Kept apart, such a truck stood in the lead's room and the lead waited beside
  // it until the handover failed (stop 67).
  const std::vector<ActorPlace> lead_waits{{1, 2037.0, 25.0, 4.5, 0}};
  const auto ahead = clear(lead_waits);
  ASSERT_TRUE(ahead.has_value());
  EXPECT_EQ(ahead->lane, 0);
  EXPECT_GT(ahead->speed_mps, car.speed_mps);
  const TypeTable types{{1.4, true, 160.0 / 3.6}, {0.6, true, 25.0}};
  ObservedVehicle at_top = car;
  at_top.type_index = 1;
  auto clear_at_top = [&](std::vector<ActorPlace> actors) {
    return clear_out(at_top, ClearingSituation{zones, 20.0, ego, 2500.0, roles, lanes, cfg, std::move(actors), types});
  };
  const auto swap = clear_at_top(lead_waits);
  ASSERT_TRUE(swap.has_value());
  EXPECT_EQ(swap->lane, 1);
  EXPECT_DOUBLE_EQ(swap->speed_mps, 25.0);  // the edge of the band its own lane's way asked for
  const auto no_swap = clear_at_top({{1, 2037.0, 25.0}});
  ASSERT_TRUE(no_swap.has_value());
  EXPECT_EQ(no_swap->lane, 0);
  // The room is the actor's own (its length, not the vehicle's): a truck (16.5 m) whose rear is
  // 33.75 m ahead of the lead's centre is out of the lead's room (32.25 m ahead of it) and moves
  // over. With the truck's length taken for the lead's, the room reached 6 m further, and the
  // trucks the ego followed in a cut-in's zone stayed there (stop 54).
  ObservedVehicle truck = vehicle(1, 2079.0, 25.0, 0);
  truck.length_m = 16.5;
  const ClearingSituation lead_beside{zones, 20.0, ego, 2500.0, roles, lanes, cfg, {{1, 2037.0, 25.0}}};
  const auto out = clear_out(truck, lead_beside);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->lane, 1);
  truck.s_m = 2077.0;
  const auto in_room = clear_out(truck, lead_beside);
  ASSERT_TRUE(in_room.has_value());
  EXPECT_EQ(in_room->lane, 0);
}

TEST_F(EgoInTheRightLaneOfTwo, AnActorWaitsForItsStartsLaneOnlyInPlaceBesideItAndNotYetMovingOver) {
  // The lead's start in the right lane at 2540 m, 20 s from now. An actor in the left lane at the
  // ego's speed 40 m ahead is there by then: it waits for lane 0. Not one 12 m further back (on its
  // way still), nor one that is moving over already, nor one in the start's lane.
  const Slot start{Direction::kForward, 0, 2540.0, 25.0};
  const ObservedVehicle beside = vehicle(7, 2040.0, 25.0, 1);
  EXPECT_EQ(lane_waited_for(beside, start, 20.0), 0);
  ObservedVehicle on_its_way = beside;
  on_its_way.s_m = 2028.0;
  EXPECT_EQ(lane_waited_for(on_its_way, start, 20.0), -1);
  on_its_way.speed_mps = 25.6;  // but it closes the 12 m by then
  EXPECT_EQ(lane_waited_for(on_its_way, start, 20.0), 0);
  ObservedVehicle moving_over = beside;
  moving_over.target_lane = 0;
  EXPECT_EQ(lane_waited_for(moving_over, start, 20.0), -1);
  EXPECT_EQ(lane_waited_for(vehicle(7, 2040.0, 25.0, 0), start, 20.0), -1);
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
  // At the actor's command, not dropping back in its lane to find a gap in the other one.
  EXPECT_EQ(way->speed_mps, 27.0);
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
