// The director bench's interval of a success rate (tests/bench/play_runs.hpp, wilson_interval):
// the Wilson score interval, checked against values worked out by hand and its symmetries.
#include <gtest/gtest.h>

#include "play_runs.hpp"

namespace entourage::bench {
namespace {

TEST(RateInterval, FortyFiveOfFiftyIsSeventyNineToNinetySixPercent) {
  // p 0.9, n 50, z 1.96: centre (0.9 + z^2/100) / (1 + z^2/50) = 0.8715, half width
  // z sqrt(0.0018 + z^2/10000) / (1 + z^2/50) = 0.0851.
  const RateInterval i = wilson_interval(45, 50);
  EXPECT_NEAR(i.low, 0.7864, 1e-4);
  EXPECT_NEAR(i.high, 0.9565, 1e-4);
}

TEST(RateInterval, AllOrNoneLeavesRoomOnOneSideOnly) {
  const RateInterval all = wilson_interval(50, 50);
  EXPECT_NEAR(all.low, 0.9287, 1e-4);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
  const RateInterval none = wilson_interval(0, 50);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 1.0 - 0.9287, 1e-4);
}

TEST(RateInterval, SuccessesAndFailuresMirrorAndMoreRunsNarrowIt) {
  for (int k = 0; k <= 50; ++k) {
    const RateInterval i = wilson_interval(k, 50);
    const RateInterval m = wilson_interval(50 - k, 50);
    EXPECT_NEAR(i.low, 1.0 - m.high, 1e-12) << k;
    EXPECT_LE(i.low, k / 50.0) << k;
    EXPECT_GE(i.high, k / 50.0) << k;
  }
  const RateInterval fifty = wilson_interval(45, 50);
  const RateInterval two_hundred = wilson_interval(180, 200);
  EXPECT_LT(two_hundred.high - two_hundred.low, 0.6 * (fifty.high - fifty.low));
  const RateInterval nothing = wilson_interval(0, 0);
  EXPECT_DOUBLE_EQ(nothing.low, 0.0);
  EXPECT_DOUBLE_EQ(nothing.high, 1.0);
}

}  // namespace
}  // namespace entourage::bench
