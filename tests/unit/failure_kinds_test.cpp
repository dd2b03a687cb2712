// The director bench's failure kinds (tests/bench/failure_kinds.hpp): the reasons a play's start
// condition was not met, grouped by role and kind, with an actor left behind the ego apart.
#include <gtest/gtest.h>

#include "failure_kinds.hpp"

namespace entourage::bench {
namespace {

// A slow truck 45 m ahead of the ego and an oncoming car 200 m ahead, as in the shipped play.
PlayConfig slow_truck() {
  PlayConfig play;
  PlayRoleConfig truck;
  truck.name = "truck";
  truck.ahead_m = 45.0;
  PlayRoleConfig oncoming;
  oncoming.name = "oncoming 1";
  oncoming.direction = Direction::kBackward;
  oncoming.ahead_m = 200.0;
  play.roles = {truck, oncoming};
  return play;
}

TEST(FailureKinds, GroupsEachProblemByItsRoleAndKind) {
  const PlayConfig play = slow_truck();
  EXPECT_EQ(kind_of("truck: 20.0 m from its start position", play), "truck: position");
  EXPECT_EQ(kind_of("truck: -13.8 km/h from its start speed", play), "truck: speed");
  EXPECT_EQ(kind_of("truck: in lane 1, not 0", play), "truck: lane");
  EXPECT_EQ(kind_of("truck: no actor", play), "truck: no actor");
  EXPECT_EQ(kind_of("vehicle 10 in a clear zone", play), "a vehicle in a clear zone");
  EXPECT_EQ(kind_of("something new", play), "something new");
}

TEST(FailureKinds, AnActorThatShouldBeAheadOfTheEgoButIsBehindItIsItsOwnKind) {
  const PlayConfig play = slow_truck();
  // 45 m ahead at the start: 44 m short is still ahead of the ego, 46 m short is behind it.
  EXPECT_EQ(kind_of("truck: -44.0 m from its start position", play), "truck: position");
  EXPECT_EQ(kind_of("truck: -46.0 m from its start position", play), "truck: behind the ego");
  EXPECT_EQ(kind_of("truck: -244.2 m from its start position", play), "truck: behind the ego");
  // Oncoming roles meet the ego: never "behind" it in this sense.
  EXPECT_EQ(kind_of("oncoming 1: -260.0 m from its start position", play), "oncoming 1: position");
  // A role of the ego's direction that starts behind the ego, and one the play does not have.
  PlayConfig behind = play;
  behind.roles[0].ahead_m = -30.0;
  EXPECT_EQ(kind_of("truck: -50.0 m from its start position", behind), "truck: position");
  EXPECT_EQ(kind_of("lead: -300.0 m from its start position", play), "lead: position");
}

TEST(FailureKinds, ReadsAListAndAFailedReportsFirstReason) {
  const PlayConfig play = slow_truck();
  EXPECT_EQ(kinds_of("truck: -244.2 m from its start position; oncoming 1: 84.2 m from its start position; "
                     "truck: -10.0 km/h from its start speed; vehicle 3 in a clear zone; vehicle 4 in a clear zone",
                     play),
            (std::set<std::string>{"truck: behind the ego", "oncoming 1: position", "truck: speed",
                                   "a vehicle in a clear zone"}));
  EXPECT_TRUE(kinds_of("", play).empty());
  EXPECT_EQ(cause_of("start condition not met on passing trigger point 2: truck: -244.2 m from its start position; "
                     "nor 6.0 s beyond it: truck: -299.0 m from its start position",
                     play),
            "truck: behind the ego");
  EXPECT_EQ(cause_of("no actor could be cast for truck", play), "no actor could be cast for truck");
}

}  // namespace
}  // namespace entourage::bench
