// Cowan's M3 composite headways (traffic/headways.hpp): the closed forms, the draws against them,
// the Poisson special case, and the scenario's validation of the parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/random.hpp"
#include "scenario/loader.hpp"
#include "traffic/headways.hpp"

namespace entourage {
namespace {

constexpr double kFlow_per_s = 450.0 / 3600.0;

TEST(CompositeHeadways, ClosedFormsAtHandComputedValues) {
  const CompositeHeadways h{0.7, 1.5};
  // lambda = alpha q / (1 - Delta q) = 0.7 * 0.125 / (1 - 0.1875) = 0.107692 1/s.
  EXPECT_NEAR(h.decay_per_s(kFlow_per_s), 0.0875 / 0.8125, 1e-12);
  EXPECT_DOUBLE_EQ(h.share_below(kFlow_per_s, 1.5), 0.0);
  // P(h < 3) = 1 - 0.7 exp(-lambda * 1.5) = 0.40377.
  EXPECT_NEAR(h.share_below(kFlow_per_s, 3.0), 1.0 - 0.7 * std::exp(-1.5 * 0.0875 / 0.8125), 1e-12);
  EXPECT_NEAR(h.mean_platoon_size(kFlow_per_s, 3.0), 1.0 / (0.7 * std::exp(-1.5 * 0.0875 / 0.8125)), 1e-12);
  EXPECT_FALSE(h.poisson());
  EXPECT_TRUE((CompositeHeadways{1.0, 0.0}).poisson());
}

TEST(CompositeHeadways, DrawsHaveTheMeanHeadwayOfTheFlowAndTheBunchedShare) {
  const CompositeHeadways h{0.7, 1.5};
  Random rng(11);
  const int n = 200000;
  double sum = 0.0;
  int at_minimum = 0;
  int below_3s = 0;
  for (int i = 0; i < n; ++i) {
    const double x = draw_headway_s(h, kFlow_per_s, rng);
    ASSERT_GE(x, 1.5);
    sum += x;
    at_minimum += x == 1.5 ? 1 : 0;
    below_3s += x < 3.0 ? 1 : 0;
  }
  EXPECT_NEAR(sum / n, 1.0 / kFlow_per_s, 0.05);  // 8 s
  EXPECT_NEAR(static_cast<double>(at_minimum) / n, 0.3, 0.005);
  EXPECT_NEAR(static_cast<double>(below_3s) / n, h.share_below(kFlow_per_s, 3.0), 0.005);
}

TEST(CompositeHeadways, AllFreeWithoutMinimumIsExponential) {
  const CompositeHeadways h{1.0, 0.0};
  EXPECT_NEAR(h.share_below(kFlow_per_s, 3.0), 1.0 - std::exp(-kFlow_per_s * 3.0), 1e-12);
}

TEST(CompositeHeadways, ASaturatedStreamHasOnlyMinimumHeadways) {
  const CompositeHeadways h{0.5, 2.0};
  Random rng(3);
  EXPECT_DOUBLE_EQ(draw_headway_s(h, 0.5, rng), 2.0);  // Delta q = 1
}

TEST(CompositeHeadways, TheScenarioRefusesAMinimumHeadwayTheFlowCannotKeep) {
  const std::string path = std::string(ENTOURAGE_SOURCE_DIR) + "/scenarios/rural.pbtxt";
  std::string text = scenario::load_file(path).text;
  ASSERT_FALSE(text.empty());
  const std::string good = "headways { free_share: 0.7 min_headway_s: 1.5 }";
  const auto at = text.find(good);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, good.size(), "headways { free_share: 0.7 min_headway_s: 9 }");  // 9 s x 450 veh/h > 1
  const auto l = scenario::load_text(text, "rural_bad.pbtxt");
  ASSERT_FALSE(l.ok());
  bool named = false;
  for (const auto& p : l.problems) named |= p.field == "demand.forward.headways.min_headway_s";
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace entourage
