// The director's casting: roles assigned jointly as an assignment problem, what a vehicle of the
// traffic costs for a role, and where a new vehicle is created out of the driver's sight.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core_test_util.hpp"
#include "director/core/assignment.hpp"
#include "director/core/casting.hpp"
#include "director_test_util.hpp"

namespace entourage::director {
namespace {

using testing::at_trigger2;
using testing::kInf;
using testing::lead_play;
using testing::vehicle;

TEST(Assignment, FindsTheLeastTotalCostWhereFirstComeWouldNot) {
  // Greedy (role 0 first takes its cheapest, vehicle 0) pays 1 + 100; the optimum pays 2 + 1.
  const std::vector<std::vector<double>> cost = {{1.0, 2.0}, {1.0, 100.0}};
  const std::vector<int> a = assign_roles(cost, {50.0, 50.0});
  EXPECT_EQ(a[0], 1);
  EXPECT_EQ(a[1], 0);
}

TEST(Assignment, LeavesARoleUnassignedWhenThatIsCheaperOrNothingFits) {
  EXPECT_EQ(assign_roles({{30.0}}, {10.0})[0], -1);
  EXPECT_EQ(assign_roles({{kInf, 3.0}}, {10.0})[0], 1);
  EXPECT_EQ(assign_roles({{kInf}}, {10.0})[0], -1);
  const std::vector<int> two = assign_roles({{1.0}, {1.0}}, {10.0, 10.0});  // one vehicle, two roles
  EXPECT_EQ((two[0] == 0) + (two[1] == 0), 1);
}


TEST(Casting, AVehicleThatCannotReachTheSlotInTimeOrMustPassTheEgoOnOneLaneCannotPlay) {
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{1, 1})[0];
  EXPECT_DOUBLE_EQ(slot.s_m, 3040.0);
  std::vector<ObservedVehicle> world = {vehicle(1, 2200.0, 24.0), vehicle(3, 1900.0, 30.0)};
  const CastingSituation at{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}};
  // Vehicle 1: 840 m in 40 s is 21 m/s on average, ending at 25: it must cruise below 21 (its
  // cost is that change of speed from its 24).
  const double cost = casting_cost(slot, play.roles[0], world[0], at, cfg);
  EXPECT_GT(cost, 3.0);
  EXPECT_LT(cost, 7.0);
  // A vehicle just behind the slot would have to average 3.5 m/s: outside the band.
  EXPECT_EQ(casting_cost(slot, play.roles[0], vehicle(2, 2900.0, 25.0), at, cfg), kInf);
  // Vehicle 3 is behind the ego and would have to pass it: actors do not overtake on one lane.
  EXPECT_EQ(casting_cost(slot, play.roles[0], world[1], at, cfg), kInf);
  // With two lanes it can, at the cost of the lane changes.
  const CastingSituation two{world, ego, 40.0, 3000.0, Lanes{2, 0}, {}};
  EXPECT_TRUE(std::isfinite(casting_cost(slot, play.roles[0], world[1], two, cfg)));
  // A slow vehicle ahead of vehicle 1 that it would have to get past on one lane blocks it (at
  // 10 m/s it is at 2900 m when vehicle 1 should be at 3040 m); a fast one that stays ahead, or
  // that would overtake vehicle 1, does not.
  std::vector<ObservedVehicle> with_fast = world;
  with_fast.push_back(vehicle(4, 2500.0, 22.0));
  with_fast.push_back(vehicle(5, 2100.0, 30.0));
  const CastingSituation fine{with_fast, ego, 40.0, 3000.0, Lanes{1, 1}, {}};
  EXPECT_TRUE(std::isfinite(casting_cost(slot, play.roles[0], world[0], fine, cfg)));
  world.push_back(vehicle(6, 2500.0, 10.0));
  const CastingSituation blocked{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}};
  EXPECT_EQ(casting_cost(slot, play.roles[0], world[0], blocked, cfg), kInf);
}

TEST(Casting, AVehicleThatMustPassTheEgoToReachASlotInTheEgosLaneCostsMoreThanACreation) {
  const PlayConfig play = lead_play();  // 40 m ahead of the ego, in its lane
  DirectorConfig cfg;
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const Lanes lanes{2, 0};
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), lanes)[0];
  // Vehicle 1, 50 m behind the ego in its lane, reaches the slot at 26.25 m/s on average: a small
  // change of speed and two lane changes, but it must get past the ego, whose speed is the
  // driver's, and back into the ego's lane ahead of it. A vehicle created out of sight is the
  // cheaper choice.
  const std::vector<ObservedVehicle> world{vehicle(1, 1950.0, 25.0)};
  const CastingSituation at{world, ego, 40.0, 3000.0, lanes, {}};
  const double cost = casting_cost(slot, play.roles[0], world[0], at, cfg);
  ASSERT_TRUE(std::isfinite(cost));
  EXPECT_GT(cost, cfg.max_speed_offset_mps);
  EXPECT_EQ(cast_roles({slot}, play.roles, {true}, at, cfg), std::vector<int>{-1});
  // With the ego in the other lane it only has to get past the ego beside it: it is cast.
  const EgoObservation beside = testing::ego_at(0, 2000.0, 25.0, 1);
  const CastingSituation passing{world, beside, 40.0, 3000.0, lanes, {}};
  EXPECT_LT(casting_cost(slot, play.roles[0], world[0], passing, cfg), cfg.max_speed_offset_mps);
  EXPECT_EQ(cast_roles({slot}, play.roles, {true}, passing, cfg), std::vector<int>{0});
}

TEST(Casting, OnOneLaneAVehicleWithAnotherBetweenItAndTheEgoCannotPlayARoleBehindAClearZone) {
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{1, 1})[0];
  // Vehicle 1 could reach the slot (3040 m); vehicle 2, between it and the ego, follows the ego's
  // pace and is still between them at the start, where the play wants 3 to 35 m ahead of the ego
  // clear: on one lane nothing gets it out.
  const std::vector<ObservedVehicle> world = {vehicle(1, 2200.0, 24.0), vehicle(2, 2100.0, 25.0)};
  const std::vector<ZoneAtStart> zones = {{Direction::kForward, 0, 3003.0, 3035.0}};
  const CastingSituation zoned{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}, zones};
  EXPECT_TRUE(stuck_between(slot, world[0].s_m, world[0].id, zoned));
  EXPECT_EQ(casting_cost(slot, play.roles[0], world[0], zoned, cfg), kInf);
  // Vehicle 2 itself has nobody between it and the ego.
  EXPECT_FALSE(stuck_between(slot, world[1].s_m, world[1].id, zoned));
  // Without a zone in the way, or with a second lane to clear it into, vehicle 1 may play.
  const CastingSituation open{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}};
  EXPECT_TRUE(std::isfinite(casting_cost(slot, play.roles[0], world[0], open, cfg)));
  const CastingSituation two{world, ego, 40.0, 3000.0, Lanes{2, 0}, {}, zones};
  EXPECT_FALSE(stuck_between(slot, world[0].s_m, world[0].id, two));
  // Nor where the play opens a gap in the oncoming traffic, in which vehicle 2 may pass it.
  CastingSituation gap{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}, zones};
  gap.oncoming_gap = true;
  EXPECT_FALSE(stuck_between(slot, world[0].s_m, world[0].id, gap));
  EXPECT_TRUE(std::isfinite(casting_cost(slot, play.roles[0], world[0], gap, cfg)));
  // Unless vehicle 2's drivers never overtake (a truck): the gap does not get it out.
  CastingSituation gap_truck = gap;
  gap_truck.types = {{0.0, false}};
  EXPECT_TRUE(stuck_between(slot, world[0].s_m, world[0].id, gap_truck));
  EXPECT_EQ(casting_cost(slot, play.roles[0], world[0], gap_truck, cfg), kInf);
  gap_truck.types = {{0.0, true}};
  EXPECT_FALSE(stuck_between(slot, world[0].s_m, world[0].id, gap_truck));
  // Nor is a vehicle created out of sight beyond vehicle 2 any better (20 s to go: a place ahead
  // is found without the zone, none with it).
  ScenarioConfig sc = testing::road_scenario(1, 1);
  const WindowBounds w = WindowBounds::around(ego.s_m, sc.window);
  const std::vector<ObservedVehicle> only_2 = {world[1]};
  const CastingSituation create_open{only_2, ego, 20.0, 3000.0, Lanes{1, 1}, {}};
  const CastingSituation create_zoned{only_2, ego, 20.0, 3000.0, Lanes{1, 1}, {}, zones};
  EXPECT_TRUE(hidden_placement(slot, 4.5, create_open, w, cfg).has_value());
  EXPECT_FALSE(hidden_placement(slot, 4.5, create_zoned, w, cfg).has_value());
}

TEST(Casting, OnOneLaneATruckAheadOfTheEgoMayPlayThoughItsPlanMissesByMoreThanAnotherMay) {
  // A truck of the traffic ahead of the ego stays between the ego and any place beyond it: where it
  // fits the role it is the only actor possible, and may miss by up to two tolerances.
  PlayConfig play = lead_play();
  play.roles[0].type_index = 1;
  DirectorConfig cfg;
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{1, 1})[0];
  ObservedVehicle truck = vehicle(1, 2280.0, 25.0);
  truck.type_index = 1;
  const std::vector<ObservedVehicle> world = {vehicle(2, 2280.0, 25.0), truck};
  CastingSituation at{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}};
  at.oncoming_gap = true;
  // 280 m ahead with 40 s to go, its best plan (the band's low edge, 17 m/s) leaves it 11 m beyond
  // the slot, more than half the role's 10 m tolerance.
  at.types = {{0.0, true}, {0.0, true}};
  EXPECT_EQ(casting_cost(slot, play.roles[0], truck, at, cfg), kInf);
  at.types = {{0.0, true}, {0.0, false}};
  EXPECT_TRUE(std::isfinite(casting_cost(slot, play.roles[0], truck, at, cfg)));
  // Not 31 m beyond it, nor with a second lane to get past it by.
  ObservedVehicle farther = truck;
  farther.s_m = 2300.0;
  EXPECT_EQ(casting_cost(slot, play.roles[0], farther, at, cfg), kInf);
  CastingSituation two_lanes = at;
  two_lanes.lanes = Lanes{2, 0};
  EXPECT_EQ(casting_cost(slot, play.roles[0], truck, two_lanes, cfg), kInf);
  // Where nothing can be created, the cheapest vehicle that fits plays (the car does not fit a
  // truck's role), unless it is taken or unavailable.
  EXPECT_EQ(cheapest_fit(slot, play.roles[0], {true, true}, at, {-1}, cfg), 1);
  EXPECT_EQ(cheapest_fit(slot, play.roles[0], {true, true}, at, {1}, cfg), -1);
  EXPECT_EQ(cheapest_fit(slot, play.roles[0], {true, false}, at, {-1}, cfg), -1);
}

TEST(Casting, NewVehiclesAreCreatedOutOfSightWithASafeGap) {
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  ScenarioConfig sc = testing::road_scenario(2, 0);
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const WindowBounds w = WindowBounds::around(ego.s_m, sc.window);
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{2, 0})[0];
  for (double t : {10.0, 20.0, 30.0, 40.0, 60.0}) {
    std::vector<ObservedVehicle> world;
    const CastingSituation at{world, ego, t, 3000.0, Lanes{2, 0}, {}};
    const auto place = hidden_placement(slot, 4.5, at, w, cfg);
    if (!place) continue;
    EXPECT_TRUE(place->s_m >= w.inner_front_m + cfg.hidden_margin_m || place->s_m <= w.inner_rear_m - cfg.hidden_margin_m)
        << "created at " << place->s_m << " with " << t << " s to go";
    EXPECT_TRUE(transport_band(slot, cfg).contains(place->speed_mps));
  }
  // 30 s to go: the ideal place (750 m behind the slot) is in view; the nearest hidden one ahead,
  // 50 m beyond the inner region, needs 19.7 m/s, within the band.
  std::vector<ObservedVehicle> world;
  const CastingSituation at{world, ego, 30.0, 3000.0, Lanes{2, 0}, {}};
  ASSERT_TRUE(hidden_placement(slot, 4.5, at, w, cfg).has_value());
  const auto free_place = *hidden_placement(slot, 4.5, at, w, cfg);
  EXPECT_DOUBLE_EQ(free_place.s_m, w.inner_front_m + cfg.hidden_margin_m);
  EXPECT_NEAR(free_place.speed_mps, 19.67, 0.01);
  // Occupied there: it moves on to a free place.
  world = {vehicle(9, free_place.s_m + 5.0, 25.0)};
  const CastingSituation busy{world, ego, 30.0, 3000.0, Lanes{2, 0}, {}};
  const auto moved = hidden_placement(slot, 4.5, busy, w, cfg);
  ASSERT_TRUE(moved.has_value());
  EXPECT_GT(std::abs(moved->s_m - world[0].s_m), 4.5 + 5.0 + 1.5 * 25.0 - 1e-9);
}

TEST(Casting, OnOneLaneAVehicleOutOfSightIsTakenOffWhereItAloneKeepsAPlaceFromBeingFree) {
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  ScenarioConfig sc = testing::road_scenario(1, 1, RoadKind::kRural);
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const WindowBounds w = WindowBounds::around(ego.s_m, sc.window);
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), Lanes{1, 1})[0];
  const double truck_m = 16.5;
  // A column of cars at 25 m/s, 60 m apart, through the whole outer region ahead: 49.5 m between
  // bumpers, where a truck needs 5 m and 1.5 s at the follower's speed on either side.
  std::vector<ObservedVehicle> world;
  VehicleId id = 10;
  for (double s = w.inner_front_m + 10.0; s < w.front_edge_m; s += 60.0) world.push_back(vehicle(id++, s, 25.0));
  const CastingSituation at{world, ego, 30.0, 3000.0, Lanes{1, 1}, {}};
  ASSERT_FALSE(hidden_placement(slot, truck_m, at, w, cfg).has_value());
  std::vector<bool> available(world.size(), true);
  const int i = blocker_to_take_off(slot, truck_m, available, at, w, cfg);
  ASSERT_GE(i, 0);
  const ObservedVehicle taken = world[static_cast<std::size_t>(i)];
  EXPECT_GT(taken.s_m, w.inner_front_m + cfg.hidden_margin_m);  // out of the driver's sight
  // Once it is gone, the truck is created where it was.
  std::vector<ObservedVehicle> after = world;
  after.erase(after.begin() + i);
  const CastingSituation gone{after, ego, 30.0, 3000.0, Lanes{1, 1}, {}};
  const auto place = hidden_placement(slot, truck_m, gone, w, cfg);
  ASSERT_TRUE(place.has_value());
  EXPECT_LT(std::abs(place->s_m - taken.s_m), 60.0 - 1e-9);
  // Vehicles that are not the director's to take (actors, cleared ones) are left alone.
  available[static_cast<std::size_t>(i)] = false;
  EXPECT_NE(blocker_to_take_off(slot, truck_m, available, at, w, cfg), i);
  EXPECT_EQ(blocker_to_take_off(slot, truck_m, std::vector<bool>(world.size(), false), at, w, cfg), -1);
  // So is a vehicle in view, though it alone keeps the nearest place out of sight from being free.
  const double sight_m = w.inner_front_m + cfg.hidden_margin_m;
  for (const double offset_m : {-10.0, 10.0}) {
    const std::vector<ObservedVehicle> one = {vehicle(99, sight_m + offset_m, 25.0)};
    const CastingSituation edge{one, ego, 30.0, 3000.0, Lanes{1, 1}, {}};
    EXPECT_EQ(blocker_to_take_off(slot, truck_m, {true}, edge, w, cfg), offset_m > 0.0 ? 0 : -1) << offset_m;
  }
}

TEST(Casting, ANewVehicleForASlotAheadOfTheEgoInItsLaneComesFromAheadRatherThanPastTheEgo) {
  // A lead 40 m ahead of the ego in its lane at the start, the ego at 25 m/s in lane 0 of two, at
  // 2000 m: the inner region ends 400 m ahead and 200 m behind, so a hidden place is at least
  // 2450 m or at most 1750 m.
  DirectorConfig cfg;
  ScenarioConfig sc = testing::road_scenario(2, 0);
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const WindowBounds w = WindowBounds::around(ego.s_m, sc.window);
  const std::vector<ObservedVehicle> world;
  auto slot_in = [](double time_s) {
    Slot slot;
    slot.lane = 0;
    slot.s_m = 2000.0 + 25.0 * time_s + 40.0;
    slot.speed_mps = 25.0;
    return slot;
  };
  // 60 s to go: from behind it needs 29.83 m/s (4.83 above the start's speed), from ahead 18.17
  // (6.83 below). From behind it would have to get past the ego and back into its lane ahead of
  // it, as a lead created behind the ego failed to in traced runs (held behind the ego by the
  // slower traffic of the other lane): it is created ahead.
  const CastingSituation sixty{world, ego, 60.0, 2000.0 + 25.0 * 60.0, Lanes{2, 0}, {}};
  const auto ahead = hidden_placement(slot_in(60.0), 4.5, sixty, w, cfg);
  ASSERT_TRUE(ahead.has_value());
  EXPECT_EQ(ahead->region, Region::kOuterFront);
  EXPECT_NEAR(ahead->speed_mps, 1090.0 / 60.0, 1e-9);
  EXPECT_FALSE(ahead->passes_ego);
  EXPECT_DOUBLE_EQ(creation_cost_for(ahead, cfg), cfg.max_speed_offset_mps);
  // 40 s to go: from ahead it would need 14.75 m/s, outside the band; behind is the only place.
  const CastingSituation forty{world, ego, 40.0, 2000.0 + 25.0 * 40.0, Lanes{2, 0}, {}};
  const auto behind = hidden_placement(slot_in(40.0), 4.5, forty, w, cfg);
  ASSERT_TRUE(behind.has_value());
  EXPECT_EQ(behind->region, Region::kOuterRear);
  EXPECT_TRUE(behind->passes_ego);
  EXPECT_DOUBLE_EQ(creation_cost_for(behind, cfg), 2.0 * cfg.max_speed_offset_mps);
  // With the ego in the other lane the one from behind passes it beside its own lane: the smaller
  // change of speed wins again.
  const EgoObservation beside = testing::ego_at(0, 2000.0, 25.0, 1);
  const CastingSituation passing{world, beside, 60.0, 2000.0 + 25.0 * 60.0, Lanes{2, 0}, {}};
  const auto from_behind = hidden_placement(slot_in(60.0), 4.5, passing, w, cfg);
  ASSERT_TRUE(from_behind.has_value());
  EXPECT_EQ(from_behind->region, Region::kOuterRear);
  EXPECT_FALSE(from_behind->passes_ego);
}

TEST(Casting, AVehicleAheadThatMustPassSlowerOnesIsPreferredToACreationThatMustGetPastTheEgo) {
  // A lead 40 m ahead of the ego in its lane in 40 s (3040 m at 25 m/s), the ego at 2000 m in lane
  // 0 of two at 25 m/s. Car 1, 150 m ahead in the ego's lane, reaches the slot at 22.25 m/s on
  // average, but three slower vehicles ahead of it (15 m/s) will be behind the slot by then: three
  // lane changes. It costs more than a creation's flat price, less than a creation that must get
  // past the ego, and the only hidden place, 40 s before the start, is behind the ego (from ahead it
  // would need 14.75 m/s). Priced flat, the creation behind the ego won (lead vehicle, seed 126,
  // stop 53: left 125 m short when the ego sped up).
  const PlayConfig play = lead_play();
  DirectorConfig cfg;
  ScenarioConfig sc = testing::road_scenario(2, 0);
  const EgoObservation ego = testing::ego_at(0, 2000.0, 25.0);
  const WindowBounds w = WindowBounds::around(ego.s_m, sc.window);
  const Lanes lanes{2, 0};
  const Slot slot = slots_of(play, Direction::kForward, 0, at_trigger2(play, 25.0), lanes)[0];
  ASSERT_DOUBLE_EQ(slot.s_m, 3040.0);
  const std::vector<ObservedVehicle> world{vehicle(1, 2150.0, 25.0), vehicle(2, 2300.0, 15.0),
                                           vehicle(3, 2340.0, 15.0), vehicle(4, 2380.0, 15.0)};
  const CastingSituation at{world, ego, 40.0, 3000.0, lanes, {}};
  const double cost = casting_cost(slot, play.roles[0], world[0], at, cfg);
  EXPECT_GT(cost, cfg.max_speed_offset_mps);
  EXPECT_LT(cost, 2.0 * cfg.max_speed_offset_mps);
  const auto place = hidden_placement(slot, 4.5, at, w, cfg);
  ASSERT_TRUE(place.has_value());
  EXPECT_EQ(place->region, Region::kOuterRear);
  ASSERT_TRUE(place->passes_ego);
  const std::vector<bool> available{true, false, false, false};
  EXPECT_EQ(cast_roles({slot}, play.roles, available, {at}, cfg), std::vector<int>{-1});  // priced flat
  EXPECT_EQ(cast_roles({slot}, play.roles, available, {at}, cfg, {creation_cost_for(place, cfg)}),
            std::vector<int>{0});
  // No place free now: the flat price, as a place is usually found a moment later.
  EXPECT_DOUBLE_EQ(creation_cost_for(std::nullopt, cfg), cfg.max_speed_offset_mps);
}

TEST(Casting, AVehicleWhoseIdealPlaceIsBeyondTheWindowIsCreatedOnlyWithRoomLeftInTheBand) {
  // An oncoming car 200 m ahead of the ego at the start (3200 m, 22 m/s). With the ego at 2900 m
  // the window ends at 3900 m; created vehicles stay 30 m inside it.
  DirectorConfig cfg;
  ScenarioConfig sc = testing::road_scenario(1, 1);
  const EgoObservation ego = testing::ego_at(0, 2900.0, 25.0);
  const WindowBounds w = WindowBounds::around(ego.s_m, sc.window);
  Slot slot;
  slot.direction = Direction::kBackward;
  slot.lane = 0;
  slot.s_m = 3200.0;
  slot.speed_mps = 22.0;
  const std::vector<ObservedVehicle> world;
  // 40 s to go: the ideal place (4080 m) is beyond the window; at its edge the car would have to
  // wait at 16.75 m/s, 5.25 below the start speed (more than half the band's 8): not yet.
  const CastingSituation early{world, ego, 40.0, 3000.0, Lanes{1, 1}, {}};
  EXPECT_TRUE(transport_band(slot, cfg).contains((w.front_edge_m - 30.0 - slot.s_m) / 40.0));
  EXPECT_FALSE(hidden_placement(slot, 4.5, early, w, cfg).has_value());
  // 35 s to go: at the edge it needs 19.1 m/s.
  const CastingSituation later{world, ego, 35.0, 3000.0, Lanes{1, 1}, {}};
  const auto place = hidden_placement(slot, 4.5, later, w, cfg);
  ASSERT_TRUE(place.has_value());
  EXPECT_DOUBLE_EQ(place->s_m, w.front_edge_m - 30.0);
  EXPECT_NEAR(place->speed_mps, 670.0 / 35.0, 1e-9);
}

}  // namespace
}  // namespace entourage::director
