// The director's zone clearing (core/play_clearing.cpp): letting in, followers that keep their
// lane, the gap in the oncoming traffic and the oncoming lane kept busy behind the actor ahead.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "core_test_util.hpp"
#include "director_test_util.hpp"
#include "director/core/director_core.hpp"

namespace entourage::director {
namespace {

using testing::lead_play;
using testing::vehicle;

// The command `out` gives vehicle `id`, if any.
const ActorControl* command_for(const DirectorOutput& out, VehicleId id) {
  for (const ActorCommand& c : out.commands) {
    if (c.vehicle == id) return &c.control;
  }
  return nullptr;
}

// The minimal scenario with one play whose lead starts 250 m ahead of the ego, behind a clear zone
// in the ego's lane from 3 to 240 m ahead of it.
ScenarioConfig zone_ahead_scenario() {
  ScenarioConfig sc = testing::minimal_scenario();
  PlayConfig play = lead_play();
  play.roles[0].ahead_m = 250.0;
  play.clear = {{0, 3.0, 240.0}};
  sc.plays = {play};
  return sc;
}

// `sc` with a second vehicle type, "truck" (type index 1), whose drivers wish `top_mps` at most:
// never cast as a car's role.
ScenarioConfig with_trucks(ScenarioConfig sc, double top_mps) {
  VehicleTypeConfig truck = sc.vehicle_types.at(0);
  truck.name = "truck";
  truck.driver.desired_speed_mps.max = top_mps;
  sc.vehicle_types.push_back(truck);
  return sc;
}

// A vehicle cleared off the ego's lane that waits, indicator on, to change into the next lane
// is let in: the vehicle just behind it there holds back (one at a time), and drives on at its own
// speed once the other has moved over.
TEST(Clearing, AVehicleWaitingToLeaveAZoneIsLetInByTheOneJustBehindItInTheTargetLane) {
  DirectorCore core(zone_ahead_scenario(), 1);
  StepInput in;
  ObservedVehicle waiting = vehicle(8, 2100.0, 25.0, 0);  // 100 m ahead of the ego: in the zone
  const ObservedVehicle behind = vehicle(9, 2092.0, 26.0, 1);  // beside it, a little behind
  DirectorOutput out;
  std::optional<ActorControl> asked;  // commands are sent when they change
  for (Step k = 0; k < 3; ++k) {  // trigger point 1; cast; transporting and clearing
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind};
    out = core.step(in);
    if (const ActorControl* c = command_for(out, 8)) asked = *c;
    EXPECT_EQ(command_for(out, 9), nullptr);  // before it signals nobody holds back for it
  }
  ASSERT_TRUE(asked.has_value());
  EXPECT_EQ(asked->lane, 1);
  EXPECT_EQ(asked->speed_mps, kOwnDesiredSpeed_mps);
  in.step = 3;
  in.ego = testing::ego_at(3, 2007.5, 25.0);
  waiting.indicator = 1;  // left
  in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind};
  out = core.step(in);
  const ActorControl* holds = command_for(out, 9);
  ASSERT_NE(holds, nullptr);
  EXPECT_EQ(holds->mode, ControlMode::kTransported);
  EXPECT_EQ(holds->lane, 1);
  EXPECT_NEAR(holds->speed_mps, 25.0 - kLetIn_mps, 1e-9);
  // Another comes between them: it holds back now, and the first drives on as it likes.
  in.step = 4;
  in.ego = testing::ego_at(4, 2010.0, 25.0);
  const ObservedVehicle between = vehicle(10, 2097.0, 25.5, 1);
  in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind, between};
  out = core.step(in);
  const ActorControl* released = command_for(out, 9);
  ASSERT_NE(released, nullptr);
  EXPECT_EQ(released->speed_mps, kOwnDesiredSpeed_mps);
  const ActorControl* holds_now = command_for(out, 10);
  ASSERT_NE(holds_now, nullptr);
  EXPECT_NEAR(holds_now->speed_mps, 25.0 - kLetIn_mps, 1e-9);
  // It moves over: the one that let it in drives on as it likes, in its lane.
  in.step = 5;
  in.ego = testing::ego_at(5, 2012.5, 25.0);
  waiting.target_lane = 1;
  in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind, between};
  out = core.step(in);
  const ActorControl* after = command_for(out, 10);
  ASSERT_NE(after, nullptr);
  EXPECT_EQ(after->speed_mps, kOwnDesiredSpeed_mps);
  EXPECT_EQ(after->lane, 1);
}

// One that held back and is no longer just behind the waiting one drives on as it likes also when
// the one that came between may not hold back itself (here, a vehicle still easing back to its own
// driving after another play): until stop 69 it held back on behind that one for nothing.
TEST(Clearing, OneThatHeldBackDrivesOnWhenAnotherThatMayNotHoldBackComesBetween) {
  DirectorCore core(zone_ahead_scenario(), 1);
  StepInput in;
  ObservedVehicle waiting = vehicle(8, 2100.0, 25.0, 0);       // in the zone, asked into lane 1
  const ObservedVehicle behind = vehicle(9, 2092.0, 26.0, 1);  // beside it, a little behind
  DirectorOutput out;
  for (Step k = 0; k < 4; ++k) {  // trigger point 1; cast; clearing; the waiting one signals
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    waiting.indicator = k == 3 ? 1 : 0;
    in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind};
    out = core.step(in);
  }
  const ActorControl* holds = command_for(out, 9);
  ASSERT_NE(holds, nullptr);
  EXPECT_NEAR(holds->speed_mps, 25.0 - kLetIn_mps, 1e-9);
  in.step = 4;
  in.ego = testing::ego_at(4, 2010.0, 25.0);
  ObservedVehicle between = vehicle(10, 2097.0, 25.5, 1);
  between.control = ControlMode::kReleasing;  // no play's to command
  in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind, between};
  out = core.step(in);
  EXPECT_EQ(command_for(out, 10), nullptr);
  const ActorControl* released = command_for(out, 9);
  ASSERT_NE(released, nullptr);
  EXPECT_EQ(released->speed_mps, kOwnDesiredSpeed_mps);
  EXPECT_EQ(released->lane, 1);
}

// One that holds back behind a faster waiting vehicle is never asked above the top speed of its
// type's drivers (cut-in, seed 478: a truck holding back for a car that waited at 33 m/s was asked
// to 31 m/s, where trucks wish 26.4 at most, and drove at 27.6).
TEST(Clearing, OneHoldingBackIsNeverAskedAboveItsTypesTopSpeed) {
  DirectorCore core(with_trucks(zone_ahead_scenario(), 20.0), 1);
  StepInput in;
  ObservedVehicle waiting = vehicle(8, 2100.0, 25.0, 0);  // in the zone, asked into lane 1
  ObservedVehicle behind = vehicle(9, 2092.0, 19.5, 1);   // a truck beside it, a little behind
  behind.type_index = 1;
  for (Step k = 0; k < 4; ++k) {  // trigger point 1; cast; clearing; the waiting one signals
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    waiting.indicator = k == 3 ? 1 : 0;
    in.world_prev = {vehicle(7, 2260.0, 25.0), waiting, behind};
    const DirectorOutput out = core.step(in);
    if (k < 3) continue;
    const ActorControl* holds = command_for(out, 9);
    ASSERT_NE(holds, nullptr);
    EXPECT_EQ(holds->lane, 1);
    EXPECT_NEAR(holds->speed_mps, 20.0, 1e-9);  // not 25 - kLetIn_mps
  }
}

// A vehicle holding up an actor on its way makes way at the actor's pace, not at its own (asked only
// to change lanes, it dropped back to find a gap behind slower traffic in the other lane, with the
// actor behind it), within what its type's drivers wish.
TEST(Clearing, AVehicleMakingWayForAnActorDoesSoAtTheActorsPace) {
  DirectorCore core(with_trucks(testing::cutter_scenario(), 30.0), 1);
  StepInput in;
  const ObservedVehicle cutter = vehicle(7, 1985.0, 28.0, 1);  // just behind the ego in the left lane
  ObservedVehicle slow = vehicle(8, 2030.0, 20.0, 1);  // a truck ahead of it there
  slow.type_index = 1;
  std::optional<ActorControl> asked;
  for (Step k = 0; k < 6 && !asked; ++k) {  // trigger point 1; cast; transporting and clearing
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    in.world_prev = {cutter, slow};
    const DirectorOutput out = core.step(in);
    if (const ActorControl* c = command_for(out, 8)) asked = *c;
  }
  ASSERT_TRUE(asked.has_value());
  EXPECT_EQ(asked->mode, ControlMode::kTransported);
  EXPECT_EQ(asked->lane, 0);
  EXPECT_GT(asked->speed_mps, slow.speed_mps);  // the cutter's pace, not kOwnDesiredSpeed_mps
  EXPECT_LE(asked->speed_mps, 30.0);            // within what its type's drivers wish
}

// An actor on its way into its start's lane that waits there, indicator on, is let in the same
// way (cut-in, seed 37, stop 55: the cutter, ahead of the ego in the ego's lane, signalled for 60 s
// while a column of cleared cars 4 m/s faster passed it in the lane it was to take).
TEST(Clearing, AnActorWaitingToMoveIntoItsStartsLaneIsLetInByTheOneJustBehindItThere) {
  DirectorCore core(testing::cutter_scenario(), 1);
  StepInput in;
  ObservedVehicle cutter = vehicle(7, 2062.0, 25.0, 0);  // ahead of the ego in its lane
  const ObservedVehicle behind = vehicle(9, 2061.5, 26.0, 1);  // comes up beside it, a little behind
  std::optional<ActorControl> asked;
  for (Step k = 0; k < 3; ++k) {  // trigger point 1; cast; transporting
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    in.world_prev = {cutter};
    const DirectorOutput out = core.step(in);
    if (const ActorControl* c = command_for(out, 7)) asked = *c;
  }
  ASSERT_TRUE(asked.has_value());
  EXPECT_EQ(asked->lane, 1);
  auto asked_of_9 = [&](int indicator) -> std::optional<ActorControl> {
    DirectorCore copy = core;
    StepInput next = in;
    next.step = 3;
    next.ego = testing::ego_at(3, 2007.5, 25.0);
    ObservedVehicle signalling = cutter;
    signalling.indicator = indicator;
    next.world_prev = {signalling, behind};
    const DirectorOutput out = copy.step(next);
    const ActorControl* c = command_for(out, 9);
    return c == nullptr ? std::nullopt : std::optional<ActorControl>(*c);
  };
  const std::optional<ActorControl> holds = asked_of_9(1);  // left
  ASSERT_TRUE(holds.has_value());
  EXPECT_EQ(holds->lane, 1);
  EXPECT_NEAR(holds->speed_mps, 25.0 - kLetIn_mps, 1e-9);
  const std::optional<ActorControl> not_signalling = asked_of_9(0);
  EXPECT_FALSE(not_signalling.has_value() && not_signalling->speed_mps == 25.0 - kLetIn_mps);
}

// An actor beside its start that waits to move into its start's lane lets in a vehicle of the
// director's that must leave the actor's room there for the actor's lane: the two swap lanes
// (lead vehicle, seeds 9, 37 and 66, stop 67: a truck at its type's top speed, the ego's leader,
// stood in the lead's room, and the lead beside it waited until the handover failed). The actor
// holds back below the waiting one's speed until it has moved over, then goes on its way.
TEST(Clearing, AnActorBesideItsStartLetsInTheVehicleInItsRoomThatMustTakeTheActorsLane) {
  ScenarioConfig sc = with_trucks(testing::minimal_scenario(), 25.0);
  PlayConfig play = lead_play();
  play.roles[0].type_index = 0;  // a car
  play.clear = {{0, 3.0, 37.0}};
  sc.plays = {play};
  DirectorCore core(sc, 1);
  StepInput in;
  ObservedVehicle lead = vehicle(7, 2040.0, 25.0, 1);  // beside its start, 40 m ahead of the ego
  ObservedVehicle truck = vehicle(8, 2064.0, 25.0, 0);  // at its top speed, in the lead's room
  truck.type_index = 1;
  truck.length_m = 12.0;
  std::map<VehicleId, ActorControl> sent;
  auto step = [&](Step k) {
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    lead.s_m = in.ego.s_m + 40.0;
    truck.s_m = in.ego.s_m + 64.0;
    in.world_prev = {lead, truck};
    for (const ActorCommand& c : core.step(in).commands) sent[c.vehicle] = c.control;
  };
  for (Step k = 0; k < 3; ++k) step(k);  // trigger point 1; cast; transporting and clearing
  ASSERT_EQ(sent.count(7), 1u);
  ASSERT_EQ(sent.count(8), 1u);
  EXPECT_EQ(sent.at(7).lane, 0);  // the lead to its start's lane
  EXPECT_EQ(sent.at(8).lane, 1);  // the truck out of the lead's room, into the lead's lane
  const double lead_mps = sent.at(7).speed_mps;
  EXPECT_GT(lead_mps, 25.0 - kLetIn_mps);
  // Both signal and wait: the lead holds back for the truck.
  lead.indicator = 2;   // right
  truck.indicator = 1;  // left
  step(3);
  step(4);
  EXPECT_LE(sent.at(7).speed_mps, 25.0 - kLetIn_mps + 1e-9);
  EXPECT_EQ(sent.at(7).lane, 0);
  EXPECT_EQ(sent.at(8).lane, 1);
  // The truck moves over: the lead goes on its way.
  truck.target_lane = 1;
  step(5);
  step(6);
  EXPECT_GT(sent.at(7).speed_mps, 25.0 - kLetIn_mps);
}

// One just behind a waiting vehicle in the lane it waits for does not let it in where holding back
// would hold up an actor on its way to its start in that lane (held_back_holds_up; cut-in, seed
// 243, stop 68: a car 51 m ahead of the ego held back to 23 m/s for one cleared off the ego's lane,
// and the car beside the ego and the cutter behind both slowed with it).
TEST(Clearing, NobodyLetsAnotherInByHoldingUpAnActorOnItsWay) {
  ScenarioConfig sc = with_trucks(testing::cutter_scenario(), 30.0);
  sc.plays[0].roles[0].type_index = 0;  // a car
  sc.plays[0].clear = {{0, 3.0, 400.0}};
  DirectorCore core(sc, 1);
  StepInput in;
  const ObservedVehicle cutter = vehicle(7, 1990.0, 32.0, 1);  // coming up fast just behind the ego
  ObservedVehicle waiting = vehicle(8, 2200.0, 28.0, 0);       // in the zone ahead of the ego, 200 m
  ObservedVehicle behind = vehicle(9, 2192.0, 28.0, 1);        // just behind it in the cutter's lane
  waiting.type_index = behind.type_index = 1;                  // trucks: neither is cast as the cutter
  std::map<VehicleId, ActorControl> sent;
  auto step = [&](Step k) {
    in.step = k;
    in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
    in.world_prev = {cutter, waiting, behind};
    for (const ActorCommand& c : core.step(in).commands) sent[c.vehicle] = c.control;
  };
  for (Step k = 0; k < 3; ++k) step(k);  // trigger point 1; cast; transporting and clearing
  ASSERT_EQ(sent.count(7), 1u);
  ASSERT_EQ(sent.count(8), 1u);
  EXPECT_EQ(sent.at(7).lane, 1);
  EXPECT_GT(sent.at(7).speed_mps, waiting.speed_mps - kLetIn_mps + kHoldsUp_mps);  // it must come up fast
  EXPECT_EQ(sent.at(8).lane, 1);  // out of the zone, into the cutter's lane ahead of its room
  waiting.indicator = 1;          // left: it waits to move over
  step(3);
  step(4);
  EXPECT_TRUE(sent.count(9) == 0 || sent.at(9).speed_mps != waiting.speed_mps - kLetIn_mps);
}

// On one lane per direction a vehicle that passes the ego during the preparation is caught between
// it and an actor ahead of it: the vehicles behind the ego in its lane, within the inner region,
// keep their lane (pass nobody) while a zone lies ahead of the ego; not on a road with a second
// lane in the ego's direction, nor vehicles further back or in the oncoming lane.
TEST(Clearing, OnOneLanePerDirectionTheEgosFollowersKeepTheirLaneWhileAZoneLiesAheadOfIt) {
  auto commands_after_preparing = [](int lanes_forward) {
    ScenarioConfig sc = testing::minimal_scenario();
    sc.road.lanes_forward = lanes_forward;
    sc.road.lanes_backward = 1;
    sc.road.kind = RoadKind::kRural;
    PlayConfig play = lead_play();
    play.clear = {{0, 3.0, 37.0}};
    sc.plays = {play};
    DirectorCore core(sc, 1);
    const double inner_behind = sc.window.inner_behind_m;
    std::map<VehicleId, ActorControl> sent;
    for (Step k = 0; k < 3; ++k) {  // trigger point 1; cast; transporting and clearing
      StepInput in;
      in.step = k;
      in.ego = testing::ego_at(k, 2000.0 + 2.5 * static_cast<double>(k), 25.0);
      in.world_prev = {vehicle(7, 2300.0, 25.0), vehicle(8, in.ego.s_m - 30.0, 26.0),
                       vehicle(9, in.ego.s_m - inner_behind - 20.0, 27.0),
                       vehicle(10, in.ego.s_m - 60.0, 22.0, 0, Direction::kBackward)};
      for (const ActorCommand& c : core.step(in).commands) sent[c.vehicle] = c.control;
    }
    return sent;
  };
  const auto rural = commands_after_preparing(1);
  ASSERT_EQ(rural.count(8), 1u);
  EXPECT_EQ(rural.at(8).mode, ControlMode::kTransported);
  EXPECT_EQ(rural.at(8).lane, 0);
  EXPECT_EQ(rural.at(8).speed_mps, kOwnDesiredSpeed_mps);
  EXPECT_EQ(rural.count(9), 0u);   // beyond the inner region
  EXPECT_EQ(rural.count(10), 0u);  // oncoming
  // With a second lane it is not held in the ego's (here, faster than the ego and heading for the
  // zone ahead of it, it is sent to the other lane instead).
  const auto freeway = commands_after_preparing(2);
  EXPECT_TRUE(freeway.count(8) == 0 || freeway.at(8).lane != 0);
}

// On one lane per direction, with a clear zone ahead of the ego, the play opens a gap in the
// oncoming traffic for the vehicles between the ego and an actor ahead of it: while the ego drives
// its first oncoming_gap_m from trigger point 1 and the role ahead of it has no actor yet (here)
// or someone between, the oncoming vehicles out of the driver's sight (beyond the inner region and
// the hidden margin, where vehicles are also created) are withdrawn. Not those in sight or behind
// the ego, not the ego's direction, not beyond that stretch, not with the gap off, not with a
// second lane in the ego's direction, not once the role has an actor with nobody between but
// vehicles in the middle of a pass.
TEST(Clearing, APlayOnOneLanePerDirectionOpensAGapInTheOncomingTrafficOutOfSight) {
  // lead_in_place: a car at the lead's start from the first step (cast as the lead), and `between`
  // of them (0: none; 1: a car between it and the ego; 2: that car in the oncoming lane, passing).
  auto withdrawn_after = [](int lanes_forward, double gap_m, double from_trigger1_m, bool lead_in_place = false,
                            int between = 0) {
    ScenarioConfig sc = testing::minimal_scenario();
    sc.road.lanes_forward = lanes_forward;
    sc.road.lanes_backward = 1;
    sc.road.kind = RoadKind::kRural;
    sc.director.oncoming_gap_m = gap_m;
    PlayConfig play = lead_play();
    play.clear = {{0, 3.0, 37.0}};
    play.roles[0].type_index = 0;
    sc.plays = {play};
    DirectorCore core(sc, 1);
    const double sight_m = sc.window.inner_ahead_m + sc.director.hidden_margin_m;
    std::set<VehicleId> withdrawn;
    for (Step k = 0; k < 3; ++k) {  // trigger point 1 (or beyond it); then preparing
      StepInput in;
      in.step = k;
      in.ego = testing::ego_at(k, play.trigger1_s_m + from_trigger1_m + 2.5 * static_cast<double>(k), 25.0);
      const double e = in.ego.s_m;
      in.world_prev = {vehicle(20, e + sight_m + 30.0, 22.0, 0, Direction::kBackward),
                       vehicle(21, e + sight_m - 30.0, 22.0, 0, Direction::kBackward),
                       vehicle(22, e + sight_m + 60.0, 25.0),
                       vehicle(23, e - 100.0, 22.0, 0, Direction::kBackward)};
      if (lead_in_place) in.world_prev.push_back(vehicle(24, e + 40.0, 25.0));
      if (between > 0) {
        ObservedVehicle other_type = vehicle(25, e + 20.0, 25.0, between == 2 ? 1 : 0);
        other_type.type_index = 1;  // cannot play the lead; a type not listed is taken to overtake
        in.world_prev.push_back(other_type);
      }
      for (const ActorCommand& c : core.step(in).commands) {
        if (c.control.mode == ControlMode::kWithdrawn) withdrawn.insert(c.vehicle);
      }
    }
    return withdrawn;
  };
  const std::set<VehicleId> only_20{20};
  EXPECT_EQ(withdrawn_after(1, 800.0, 0.0), only_20);
  EXPECT_EQ(withdrawn_after(1, 800.0, 700.0), only_20);
  EXPECT_TRUE(withdrawn_after(1, 800.0, 850.0).empty());
  EXPECT_TRUE(withdrawn_after(1, 0.0, 0.0).empty());
  EXPECT_TRUE(withdrawn_after(2, 800.0, 0.0).empty());
  EXPECT_TRUE(withdrawn_after(1, 800.0, 0.0, true).empty());
  EXPECT_EQ(withdrawn_after(1, 800.0, 0.0, true, 1), only_20);
  // A vehicle already passing is out of the way once back in: the gap closes (the ego, too, sees
  // the oncoming traffic sooner).
  EXPECT_TRUE(withdrawn_after(1, 800.0, 0.0, true, 2).empty());
}

TEST(Clearing, BehindItsActorOnOneLanePerDirectionTheEgoMeetsABusyOncomingLane) {
  // The lead cast in view 40 m ahead of the ego with nobody between (or a car between), an
  // oncoming role (a car at 80 km/h), and the oncoming lane as given: how many vehicles the play
  // creates in the oncoming lane over three steps, and where.
  struct Case {
    double gap_m = 800.0;
    double from_trigger1_m = 900.0;  // beyond the gap's stretch
    std::optional<double> oncoming_m;        // an oncoming vehicle this far beyond the driver's sight
    std::optional<double> passer_ahead_m;    // a car of the ego's direction passing, this far ahead
    bool between = false;                    // a car between the ego and the lead, in its lane
  };
  auto created = [](const Case& c) {
    ScenarioConfig sc = testing::minimal_scenario();
    sc.road.lanes_forward = 1;
    sc.road.lanes_backward = 1;
    sc.road.kind = RoadKind::kRural;
    sc.director.oncoming_gap_m = c.gap_m;
    PlayConfig play = lead_play();
    play.clear = {{0, 3.0, 37.0}};
    play.roles[0].type_index = 0;
    PlayRoleConfig oncoming;
    oncoming.name = "oncoming";
    oncoming.direction = Direction::kBackward;
    oncoming.ahead_m = 200.0;
    oncoming.speed_mps = 22.2;
    oncoming.absolute_speed = true;
    oncoming.position_tolerance_m = 50.0;
    play.roles.push_back(oncoming);
    sc.plays = {play};
    DirectorCore core(sc, 1);
    const double sight_m = sc.window.inner_ahead_m + sc.director.hidden_margin_m;
    std::vector<double> ahead_of_ego;
    for (Step k = 0; k < 3; ++k) {
      StepInput in;
      in.step = k;
      in.ego = testing::ego_at(k, play.trigger1_s_m + c.from_trigger1_m + 2.5 * static_cast<double>(k), 25.0);
      const double e = in.ego.s_m;
      in.world_prev = {vehicle(24, e + 40.0, 25.0), vehicle(26, e - 300.0, 22.0, 0, Direction::kBackward)};
      if (c.oncoming_m) in.world_prev.push_back(vehicle(20, e + sight_m + *c.oncoming_m, 22.0, 0, Direction::kBackward));
      if (c.passer_ahead_m) in.world_prev.push_back(vehicle(21, e + *c.passer_ahead_m, 27.0, 1));
      if (c.between) {
        ObservedVehicle other_type = vehicle(25, e + 20.0, 25.0);
        other_type.type_index = 1;  // cannot play the lead; a type not listed is taken to overtake
        in.world_prev.push_back(other_type);
      }
      for (const Handoff& h : core.step(in).births) {
        if (h.vehicle.direction != Direction::kBackward) continue;
        // Every vehicle created out of sight; only the autonomous ones keep the lane busy (an
        // oncoming actor created for its role is driven by the director).
        EXPECT_GE(h.vehicle.s_m - e, sight_m);
        if (h.vehicle.control.mode == ControlMode::kAutonomous) ahead_of_ego.push_back(h.vehicle.s_m - e);
      }
    }
    EXPECT_TRUE(std::all_of(ahead_of_ego.begin(), ahead_of_ego.end(), [&](double a) { return a > sight_m; }));
    return ahead_of_ego.size();
  };
  auto with = [](auto set) {
    Case c;
    set(c);
    return c;
  };
  // An empty oncoming lane out to the driver's sight: one car just beyond it, once (the second
  // step does not see it yet and counts it where it would be).
  EXPECT_EQ(created(Case{}), 1U);
  EXPECT_EQ(created(with([](Case& c) { c.oncoming_m = -250.0; })), 1U);
  EXPECT_EQ(created(with([](Case& c) { c.oncoming_m = 250.0; })), 1U);
  // An oncoming vehicle near the edge of sight, on either side: the lane is busy.
  EXPECT_EQ(created(with([](Case& c) { c.oncoming_m = -150.0; })), 0U);
  EXPECT_EQ(created(with([](Case& c) { c.oncoming_m = 150.0; })), 0U);
  // Not while someone passes between the ego and the lead (it needs the lane); once it is beyond
  // the lead, yes.
  EXPECT_EQ(created(with([](Case& c) { c.passer_ahead_m = 20.0; })), 0U);
  EXPECT_EQ(created(with([](Case& c) { c.passer_ahead_m = 60.0; })), 1U);
  // Nor for one passing behind the ego: counted, it kept the lane in front of the ego empty (slow
  // truck, seed 36, a car passing 200 m behind the ego; stop 57).
  EXPECT_EQ(created(with([](Case& c) { c.passer_ahead_m = -100.0; })), 1U);
  // Not with a car between (in the gap's stretch the gap opens instead), nor with the gap off.
  EXPECT_EQ(created(with([](Case& c) { c.between = true; })), 0U);
  EXPECT_EQ(created(with([](Case& c) {
              c.from_trigger1_m = 0.0;
              c.between = true;
            })),
            0U);
  EXPECT_EQ(created(with([](Case& c) { c.gap_m = 0.0; })), 0U);
  // Within the gap's stretch with nobody between: the lane is kept busy as well.
  EXPECT_EQ(created(with([](Case& c) { c.from_trigger1_m = 0.0; })), 1U);
}

}  // namespace
}  // namespace entourage::director
