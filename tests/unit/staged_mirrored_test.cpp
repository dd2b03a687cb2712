// The director bench's tally of where the ego passed trigger point 2 (tests/bench/play_runs.hpp,
// staged_mirrored): a play is counted mirrored when the lane the ego is in, or moving to, makes the
// director stage it mirrored (director/core/stage.hpp, staged_beside).
#include <gtest/gtest.h>

#include "core_test_util.hpp"
#include "director_test_util.hpp"
#include "play_runs.hpp"

namespace entourage::bench {
namespace {

// A cut-in: the cutter in the lane left of the ego, a zone ahead of the ego and one beside it.
PlayConfig cut_in() {
  PlayConfig play = testing::lead_play();
  play.roles[0].lane_offset = 1;
  play.clear = {{0, 3.0, 60.0}, {1, -25.0, 4.0}};
  return play;
}

TEST(StagedMirrored, ACutInBesideAnEgoInTheLeftLaneOfTwoIsMirrored) {
  const director::Lanes two{2, 0};
  EXPECT_FALSE(staged_mirrored(cut_in(), testing::ego_at(0, 5000.0, 30.0, 0), two));
  EXPECT_TRUE(staged_mirrored(cut_in(), testing::ego_at(0, 5000.0, 30.0, 1), two));
  // Moving from the right lane to the left one: staged beside the lane it moves to.
  EgoObservation moving = testing::ego_at(0, 5000.0, 30.0, 0);
  moving.target_lane = 1;
  EXPECT_TRUE(staged_mirrored(cut_in(), moving, two));
  // The middle lane of three: both sides fit, as written.
  EXPECT_FALSE(staged_mirrored(cut_in(), testing::ego_at(0, 5000.0, 30.0, 1), director::Lanes{3, 0}));
}

TEST(StagedMirrored, APlayInTheEgosLaneAloneIsNeverMirrored) {
  PlayConfig lead = testing::lead_play();
  lead.clear = {{0, 3.0, 60.0}};
  EXPECT_FALSE(staged_mirrored(lead, testing::ego_at(0, 5000.0, 30.0, 1), director::Lanes{2, 0}));
}

}  // namespace
}  // namespace entourage::bench
