// The director bench's paired comparison (tests/bench/paired_runs.hpp): the verbose lines read
// back, runs paired by seed, and McNemar's exact p-value against values worked out by hand.
#include <gtest/gtest.h>

#include "paired_runs.hpp"

namespace entourage::bench {
namespace {

TEST(PairedRuns, ReadsTheOutcomeOfEachVerboseLineWhateverTheDriver) {
  const std::string text =
      "run 0 seed 1 steady       done        pos    2.3 m speed   1.0 km/h ...\n"
      "run 1 seed 2 brakes       failed      pos   12.0 m ... start condition not met: done badly\n"
      "run 2 seed 3 changes lane done        pos    1.0 m ...\n"
      "run 3 seed 4 changes lane failed      pos   40.0 m ...\n"
      "\n== cut-in (freeway_cut_in): 4 runs ==\n"
      "success 2 / 4 (50.0 %)\n";
  const std::map<std::uint64_t, bool> o = outcomes_by_seed(text);
  ASSERT_EQ(o.size(), 4u);
  EXPECT_TRUE(o.at(1));
  EXPECT_FALSE(o.at(2));
  EXPECT_TRUE(o.at(3));
  EXPECT_FALSE(o.at(4));
}

TEST(PairedRuns, CountsTheRunsAChangeFlippedAndThoseItCannotPair) {
  const std::map<std::uint64_t, bool> before{{1, true}, {2, false}, {3, true}, {4, false}};
  const std::map<std::uint64_t, bool> now{{1, true}, {2, true}, {3, false}, {4, false}, {5, true}};
  const PairedRuns p = pair_runs(before, now);
  EXPECT_EQ(p.both_done, 1);
  EXPECT_EQ(p.gained, 1);
  EXPECT_EQ(p.lost, 1);
  EXPECT_EQ(p.both_failed, 1);
  EXPECT_EQ(p.unpaired, 1);
}

TEST(PairedRuns, PValueIsTheChanceOfAFairCoinSplittingAsUnevenly) {
  EXPECT_DOUBLE_EQ(flips_p_value(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(flips_p_value(3, 3), 1.0);
  // 5 of 5 one way: 2 / 2^5.
  EXPECT_NEAR(flips_p_value(5, 0), 0.0625, 1e-12);
  EXPECT_NEAR(flips_p_value(0, 5), 0.0625, 1e-12);
  // 9 to 1: 2 (1 + 10) / 2^10.
  EXPECT_NEAR(flips_p_value(9, 1), 22.0 / 1024.0, 1e-12);
  // 10 to 12: 2 P(X <= 10), X ~ Bin(22, 1/2) = 2 * 1744436 / 2^22.
  EXPECT_NEAR(flips_p_value(10, 12), 2.0 * 1744436.0 / 4194304.0, 1e-9);
}

TEST(PairedRuns, ManyFlipsStayFinite) {
  const double p = flips_p_value(2400, 2600);
  EXPECT_GT(p, 0.0);
  EXPECT_LT(p, 0.01);
}

}  // namespace
}  // namespace entourage::bench
