// The event director's parts: staging, the script and aiming (a play's phases:
// director_phases_test; start-time estimation: director_start_time_test; casting:
// director_casting_test; transport: director_transport_test; zone clearing: director_clearing_test).
#include <gtest/gtest.h>

#include <vector>

#include "core_test_util.hpp"
#include "director_test_util.hpp"
#include "director/core/script.hpp"
#include "director/core/stage.hpp"
#include "director/core/zones.hpp"

namespace entourage::director {
namespace {

using testing::at_trigger2;
using testing::kInf;
using testing::lead_play;
using testing::vehicle;

TEST(Staging, ARoleBesideTheEgoWaitsAheadOfItsStartUntilTheApproach) {
  PlayConfig play = lead_play();
  play.roles[0].lane_offset = 1;  // a cutter 12 m ahead in the lane left of the ego
  play.roles[0].ahead_m = 12.0;
  const DirectorConfig cfg;  // waits 50 m ahead until 25 s before the start
  const Lanes lanes{2, 0};
  const Aim aim = at_trigger2(play, 25.0);
  const Slot slot = slots_of(play, Direction::kForward, 0, aim, lanes)[0];
  // 60 s before the start: aimed at where its start is 25 s before it, 50 m further on, by then.
  const Waypoint early = way_to(slot, aim, play.roles[0], Direction::kForward, 0, lanes, 60.0, cfg);
  EXPECT_DOUBLE_EQ(early.time_s, 35.0);
  EXPECT_DOUBLE_EQ(early.slot.s_m, slot.s_m + 50.0 - 25.0 * 25.0);
  EXPECT_EQ(early.slot.lane, slot.lane);
  EXPECT_DOUBLE_EQ(early.slot.speed_mps, slot.speed_mps);
  // Within the approach: the start itself.
  const Aim within{15.0, 3000.0, 25.0, 0.0};
  const Waypoint late = way_to(slot, within, play.roles[0], Direction::kForward, 0, lanes, 15.0, cfg);
  EXPECT_DOUBLE_EQ(late.time_s, 15.0);
  EXPECT_DOUBLE_EQ(late.slot.s_m, slot.s_m);
  // A role in the ego's own lane, one far ahead of it, or no wait configured: the start.
  PlayConfig lead = lead_play();
  const Slot own = slots_of(lead, Direction::kForward, 0, at_trigger2(lead, 25.0), lanes)[0];
  const Aim lead_aim = at_trigger2(lead, 25.0);
  EXPECT_DOUBLE_EQ(way_to(own, lead_aim, lead.roles[0], Direction::kForward, 0, lanes, 60.0, cfg).slot.s_m, own.s_m);
  PlayRoleConfig far = play.roles[0];
  far.ahead_m = kBesideReach_m + 1.0;
  EXPECT_DOUBLE_EQ(way_to(slot, aim, far, Direction::kForward, 0, lanes, 60.0, cfg).time_s, 60.0);
  DirectorConfig off = cfg;
  off.beside_wait_ahead_m = 0.0;
  EXPECT_DOUBLE_EQ(way_to(slot, aim, play.roles[0], Direction::kForward, 0, lanes, 60.0, off).slot.s_m, slot.s_m);
}

TEST(Staging, ARoleTheEgoClosesOnDrivesAtItsStartSpeedForTheLastSecondsBeforeTheStart) {
  // A stopper 250 m ahead at 8 m/s below the ego's 30: 60 s before the start its way leads to
  // where its start is kSettleEarly_s before the start, by then (22 m/s x 10 s nearer).
  PlayConfig play = lead_play();
  play.roles[0].ahead_m = 250.0;
  play.roles[0].speed_mps = -8.0;
  const DirectorConfig cfg;
  const Lanes lanes{2, 0};
  const Aim aim = at_trigger2(play, 30.0);
  const Slot slot = slots_of(play, Direction::kForward, 0, aim, lanes)[0];
  const Waypoint early = way_to(slot, aim, play.roles[0], Direction::kForward, 0, lanes, 60.0, cfg);
  EXPECT_DOUBLE_EQ(early.time_s, 60.0 - kSettleEarly_s);
  EXPECT_DOUBLE_EQ(early.slot.s_m, slot.s_m - 22.0 * kSettleEarly_s);
  EXPECT_DOUBLE_EQ(early.slot.speed_mps, 22.0);
  EXPECT_EQ(early.slot.lane, slot.lane);
  // In the last kSettleEarly_s: the start itself.
  const Aim near{kSettleEarly_s, 3000.0, 30.0, 0.0};
  const Waypoint late = way_to(slot, near, play.roles[0], Direction::kForward, 0, lanes, kSettleEarly_s, cfg);
  EXPECT_DOUBLE_EQ(late.time_s, kSettleEarly_s);
  EXPECT_DOUBLE_EQ(late.slot.s_m, slot.s_m);
  // The ego closing on it by kSettleClosing_mps or less, and a slower role behind the ego: the
  // start, by the aim's time.
  PlayConfig slow = play;
  slow.roles[0].speed_mps = -kSettleClosing_mps;
  const Slot slow_slot = slots_of(slow, Direction::kForward, 0, aim, lanes)[0];
  EXPECT_DOUBLE_EQ(way_to(slow_slot, aim, slow.roles[0], Direction::kForward, 0, lanes, 60.0, cfg).time_s, 60.0);
  PlayConfig behind = play;
  behind.roles[0].ahead_m = -60.0;
  const Slot behind_slot = slots_of(behind, Direction::kForward, 0, aim, lanes)[0];
  EXPECT_DOUBLE_EQ(way_to(behind_slot, aim, behind.roles[0], Direction::kForward, 0, lanes, 60.0, cfg).slot.s_m,
                   behind_slot.s_m);
  const Lanes rural{1, 1};
  // On one lane per direction (the slow truck): the traffic behind it could not pass it in a lane
  // of its own direction, and would queue behind it for those seconds.
  const Slot one_lane_slot = slots_of(play, Direction::kForward, 0, aim, rural)[0];
  EXPECT_DOUBLE_EQ(way_to(one_lane_slot, aim, play.roles[0], Direction::kForward, 0, rural, 60.0, cfg).time_s, 60.0);
}

TEST(Staging, AnOncomingRoleDrivesAtItsStartSpeedForTheLastSecondsBeforeTheStart) {
  // An oncoming car at 22 m/s, 200 m ahead of the ego at the start: 60 s before it, its way leads
  // to where its start is kOncomingSettle_s before the start (22 m/s x 15 s further from the ego,
  // against the ego's direction), by then.
  PlayConfig play = lead_play();
  play.roles[0].direction = Direction::kBackward;
  play.roles[0].ahead_m = 200.0;
  play.roles[0].absolute_speed = true;
  play.roles[0].speed_mps = 22.0;
  const DirectorConfig cfg;
  const Lanes rural{1, 1};
  const Aim aim = at_trigger2(play, 25.0);
  const Slot slot = slots_of(play, Direction::kForward, 0, aim, rural)[0];
  ASSERT_EQ(slot.direction, Direction::kBackward);
  const Waypoint early = way_to(slot, aim, play.roles[0], Direction::kForward, 0, rural, 60.0, cfg);
  EXPECT_DOUBLE_EQ(early.time_s, 60.0 - kOncomingSettle_s);
  EXPECT_DOUBLE_EQ(early.slot.s_m, slot.s_m + 22.0 * kOncomingSettle_s);
  EXPECT_DOUBLE_EQ(early.slot.speed_mps, 22.0);
  EXPECT_EQ(early.slot.lane, slot.lane);
  // In the last kOncomingSettle_s: the start itself, by the aim's time.
  const Aim near{kOncomingSettle_s, 3000.0, 25.0, 0.0};
  const Waypoint late = way_to(slot, near, play.roles[0], Direction::kForward, 0, rural, kOncomingSettle_s, cfg);
  EXPECT_DOUBLE_EQ(late.time_s, kOncomingSettle_s);
  EXPECT_DOUBLE_EQ(late.slot.s_m, slot.s_m);
}

TEST(Staging, AnEgoOvertakingInTheOncomingLaneKeepsThePlayStagedBesideItsOwnLane) {
  PlayConfig play = lead_play();
  play.clear = {{0, 3.0, 50.0}};
  const Lanes rural{1, 1};
  // Passing on a two-lane road, the ego drives in lane 1 of its direction's numbering: the
  // oncoming lane. The play stays staged beside lane 0, where it comes back, and its zone stays.
  EgoObservation passing = testing::ego_at(0, 2000.0, 25.0, 1);
  EXPECT_EQ(staging_lane(passing, rural), 0);
  const std::vector<ZoneAtStart> zones = zones_of(play, Direction::kForward, staging_lane(passing, rural), 3000.0, rural);
  ASSERT_EQ(zones.size(), 1U);
  EXPECT_EQ(zones[0].lane, 0);
  EXPECT_TRUE(zones_of(play, Direction::kForward, passing.target_lane, 3000.0, rural).empty());  // what it was
  // Moving back: its target lane. On a freeway every lane it uses is its own.
  passing.target_lane = 0;
  EXPECT_EQ(staging_lane(passing, rural), 0);
  EXPECT_EQ(staging_lane(testing::ego_at(0, 2000.0, 25.0, 1), Lanes{2, 2}), 1);
}

TEST(Staging, APlayThatDoesNotFitBesideTheEgosLaneIsMirrored) {
  PlayConfig play = lead_play();
  play.roles[0].lane_offset = 1;  // a cutter in the lane left of the ego
  play.clear = {{0, 3.0, 60.0}, {1, -25.0, 4.0}};
  PlayActionConfig signal;
  signal.kind = PlayActionKind::kIndicator;
  signal.indicator = 2;  // right
  PlayActionConfig cut;
  cut.kind = PlayActionKind::kLaneChange;
  cut.lane_offset = -1;
  play.actions = {signal, cut};
  // The ego in the right lane of two: as written.
  EXPECT_EQ(staged_beside(play, 0, Lanes{2, 0}).roles[0].lane_offset, 1);
  // In the left lane: from the right, signalling left, changing left.
  const PlayConfig m = staged_beside(play, 1, Lanes{2, 0});
  EXPECT_EQ(m.roles[0].lane_offset, -1);
  EXPECT_EQ(m.clear[1].lane_offset, -1);
  EXPECT_EQ(m.actions[0].indicator, 1);
  EXPECT_EQ(m.actions[1].lane_offset, 1);
  EXPECT_EQ(slots_of(m, Direction::kForward, 1, at_trigger2(m, 25.0), Lanes{2, 0})[0].lane, 0);
  // The middle lane of three: both sides fit, as written.
  EXPECT_EQ(staged_beside(play, 1, Lanes{3, 0}).roles[0].lane_offset, 1);
}

// --- Script

TEST(Script, ActionsOfARoleRunInOrderWhenTheirConditionsHold) {
  PlayConfig play = lead_play();
  PlayActionConfig brake;
  brake.role = 0;
  brake.at_s = 2.0;
  brake.kind = PlayActionKind::kSpeed;
  brake.speed_mps = 0.0;
  brake.rate_mps2 = 6.0;
  PlayActionConfig blink;
  blink.role = 0;
  blink.kind = PlayActionKind::kIndicator;
  blink.indicator = 2;
  play.actions = {brake, blink};
  Script script(play);
  const EgoObservation ego = testing::ego_at(0, 3000.0, 25.0);
  const ObservedVehicle lead = vehicle(1, 3040.0, 25.0);
  std::vector<ActorControl> controls(1);
  controls[0].speed_mps = 25.0;
  EXPECT_EQ(script.step(1.0, ego, {&lead}, controls, 2), 0U);  // not yet: at 2 s; the indicator waits its turn
  EXPECT_EQ(controls[0].indicator, 0);
  EXPECT_EQ(script.step(2.0, ego, {&lead}, controls, 2), 2U);
  EXPECT_DOUBLE_EQ(controls[0].speed_mps, 0.0);
  EXPECT_DOUBLE_EQ(controls[0].decel_mps2, 6.0);
  EXPECT_EQ(controls[0].indicator, 2);
}

TEST(Script, TimeToCollisionIsTheGapOverTheClosingSpeed) {
  const EgoObservation ego = testing::ego_at(0, 1000.0, 30.0);
  EXPECT_NEAR(time_to_collision_s(ego, vehicle(1, 1050.0, 20.0)), (50.0 - 4.55) / 10.0, 1e-9);
  EXPECT_EQ(time_to_collision_s(ego, vehicle(1, 1050.0, 35.0)), kInf);
  // Oncoming: closing at the sum of the speeds.
  EXPECT_NEAR(time_to_collision_s(ego, vehicle(2, 1300.0, 20.0, 0, Direction::kBackward)), (300.0 - 4.55) / 50.0, 1e-9);
}


// --- Aiming

TEST(Aim, FarFromTheStartActorsAimAtTriggerPoint2NearItAShortHorizonAhead) {
  const EgoObservation ego = testing::ego_at(0, 2900.0, 25.0);
  const Aim far = aim_of(30.0, 3000.0, 24.0, ego, 4.0);
  EXPECT_DOUBLE_EQ(far.time_s, 30.0);
  EXPECT_DOUBLE_EQ(far.ego_s_m, 3000.0);
  EXPECT_DOUBLE_EQ(far.ego_speed_mps, 24.0);
  EXPECT_DOUBLE_EQ(far.past_start_s, 0.0);
  const Aim near = aim_of(1.0, 3000.0, 24.0, ego, 4.0);
  EXPECT_DOUBLE_EQ(near.time_s, 4.0);
  EXPECT_DOUBLE_EQ(near.ego_s_m, 3000.0);  // 2900 + 25 m/s x 4 s
  EXPECT_DOUBLE_EQ(near.past_start_s, 3.0);
  // A role slower than the ego by 5 m/s stands 40 m ahead at the start, 25 m ahead 3 s later; an
  // oncoming one at 20 m/s comes 45 m/s closer each second. The play is aimed late rather than
  // early (the handover may wait for an actor still too far): by 25 / 45 s, which puts the oncoming
  // role half its position tolerance (50 m) beyond its start, and the slower one 5 m/s times that
  // beyond its own (within its 10 m tolerance either way).
  PlayConfig play = lead_play();
  play.roles[0].speed_mps = -5.0;
  PlayRoleConfig oncoming;
  oncoming.name = "oncoming";
  oncoming.direction = Direction::kBackward;
  oncoming.ahead_m = 300.0;
  oncoming.absolute_speed = true;
  oncoming.speed_mps = 20.0;
  oncoming.position_tolerance_m = 50.0;
  play.roles.push_back(oncoming);
  const double late_s = 25.0 / 45.0;
  EXPECT_DOUBLE_EQ(late_aim_s(play, Direction::kForward, 25.0), late_s);
  const std::vector<Slot> slots = slots_of(play, Direction::kForward, 0, near, Lanes{1, 1});
  EXPECT_DOUBLE_EQ(slots[0].s_m, 3000.0 + 40.0 + 5.0 * late_s - 5.0 * 3.0);
  EXPECT_DOUBLE_EQ(slots[0].speed_mps, 20.0);
  EXPECT_DOUBLE_EQ(slots[1].s_m, 3000.0 + 300.0 + 25.0 - 45.0 * 3.0);
  // For an ego driving the other way, beyond its start the other way.
  const Aim at_start{10.0, 3000.0, 25.0, 0.0};
  const std::vector<Slot> other = slots_of(play, Direction::kBackward, 0, at_start, Lanes{1, 1});
  EXPECT_DOUBLE_EQ(other[0].s_m, 3000.0 - 40.0 - 5.0 * late_s);
  EXPECT_DOUBLE_EQ(other[1].s_m, 3000.0 - 300.0 - 25.0);
  EXPECT_EQ(other[1].direction, Direction::kForward);
}

TEST(Aim, OnlyRolesTheEgoClosesOnAreAimedBeyondTheirStart) {
  const Aim at_start{10.0, 3000.0, 30.0, 0.0};
  // Alone, a role 8 m/s slower than the ego (the stopped vehicle's, at 80 km/h before it stops)
  // is aimed half its 20 m tolerance beyond its start: 10 m further ahead.
  PlayConfig stopper = lead_play();
  stopper.roles[0].ahead_m = 250.0;
  stopper.roles[0].speed_mps = -8.0;
  stopper.roles[0].position_tolerance_m = 20.0;
  EXPECT_DOUBLE_EQ(late_aim_s(stopper, Direction::kForward, 30.0), 10.0 / 8.0);
  EXPECT_DOUBLE_EQ(slots_of(stopper, Direction::kForward, 0, at_start, Lanes{2, 0})[0].s_m, 3000.0 + 250.0 + 10.0);
  // One faster than the ego behind it: 5 m further behind.
  PlayConfig chaser = lead_play();
  chaser.roles[0].ahead_m = -60.0;
  chaser.roles[0].speed_mps = 4.0;
  EXPECT_DOUBLE_EQ(slots_of(chaser, Direction::kForward, 0, at_start, Lanes{2, 0})[0].s_m, 3000.0 - 60.0 - 5.0);
  // The ego does not close on a role at its speed (the lead vehicle), one faster ahead of it (the
  // cutter) or one slower behind it: they are aimed at their start, and a play of only such roles
  // is not aimed late.
  PlayConfig others = lead_play();
  others.roles[0].speed_mps = 0.0;
  PlayRoleConfig cutter = others.roles[0];
  cutter.ahead_m = 12.0;
  cutter.speed_mps = 1.4;
  PlayRoleConfig follower = others.roles[0];
  follower.ahead_m = -30.0;
  follower.speed_mps = -2.0;
  others.roles.push_back(cutter);
  others.roles.push_back(follower);
  EXPECT_DOUBLE_EQ(late_aim_s(others, Direction::kForward, 30.0), 0.0);
  const std::vector<Slot> slots = slots_of(others, Direction::kForward, 0, at_start, Lanes{2, 0});
  EXPECT_DOUBLE_EQ(slots[0].s_m, 3040.0);
  EXPECT_DOUBLE_EQ(slots[1].s_m, 3012.0);
  EXPECT_DOUBLE_EQ(slots[2].s_m, 2970.0);
}

}  // namespace
}  // namespace entourage::director
