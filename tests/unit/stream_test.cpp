// The stream seen from a moving window: the moving-observer relations (Wardrop 1952).
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"
#include "traffic/stream.hpp"

namespace entourage {
namespace {

StreamModel freeway_like() {
  // 0.5 veh/s: cars N(33, 3) m/s in [25, 42], trucks N(24, 1) m/s in [22, 26], 80/20
  return StreamModel(0.5, {{0, 0.8, {33.0, 3.0, 25.0, 42.0}}, {1, 0.2, {24.0, 1.0, 22.0, 26.0}}});
}

TEST(Stream, WardropRelationHoldsAtEveryWindowSpeed) {
  const StreamModel m = freeway_like();
  for (double u : {0.0, 10.0, 24.0, 30.0, 45.0}) {
    EXPECT_NEAR(m.rate_rear_per_s(u) - m.rate_front_per_s(u), m.flow_veh_per_s() - m.density_per_m() * u, 1e-9)
        << "u = " << u;
  }
}

TEST(Stream, AStandingWindowIsAnOrdinarySource) {
  const StreamModel m = freeway_like();
  EXPECT_NEAR(m.rate_rear_per_s(0.0), 0.5, 1e-12);
  EXPECT_NEAR(m.rate_front_per_s(0.0), 0.0, 1e-12);
  EXPECT_NEAR(m.rate_oncoming_per_s(0.0), 0.5, 1e-12);
}

TEST(Stream, NothingEntersFromBehindFasterThanTheFastest) {
  const StreamModel m = freeway_like();
  EXPECT_NEAR(m.rate_rear_per_s(42.5), 0.0, 1e-12);
  EXPECT_GT(m.rate_front_per_s(42.5), 0.0);
}

TEST(Stream, DensityIsFlowTimesMeanInverseSpeed) {
  const StreamModel one(0.5, {{0, 1.0, {25.0, 0.0, 25.0, 25.0}}});
  EXPECT_NEAR(one.density_per_m(), 0.5 / 25.0, 1e-12);
  EXPECT_NEAR(one.mean_space_speed_mps(), 25.0, 1e-12);
  const StreamModel m = freeway_like();
  EXPECT_LT(m.mean_space_speed_mps(), m.mean_time_speed_mps());  // slow vehicles over-represented on the road
}

TEST(Stream, DrawsFollowTheirConditionalDistributions) {
  const StreamModel m = freeway_like();
  Random rng(7);
  const double u = 30.0;
  double rear_min = 1e9;
  double front_max = 0.0;
  double sum_time = 0.0;
  double sum_space = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    rear_min = std::min(rear_min, m.draw_rear(rng, u).speed_mps);
    front_max = std::max(front_max, m.draw_front(rng, u).speed_mps);
    sum_time += m.draw_time_mean(rng).speed_mps;
    sum_space += 1.0 / m.draw_space_mean(rng).speed_mps;
  }
  EXPECT_GT(rear_min, u - 0.1);    // from behind only faster vehicles (up to a bin's width)
  EXPECT_LT(front_max, u + 0.1);   // from ahead only slower ones
  EXPECT_NEAR(sum_time / n, m.mean_time_speed_mps(), 0.1);
  // E_f[1/v] = E_g[1/v^2] / E_g[1/v]
  const double e_inv2 = m.expect([](double v) { return 1.0 / (v * v); });
  const double e_inv = m.expect([](double v) { return 1.0 / v; });
  EXPECT_NEAR(sum_space / n, e_inv2 / e_inv, 2e-4);
}

TEST(Stream, TypeSharesAreKeptInDraws) {
  const StreamModel m = freeway_like();
  Random rng(3);
  int trucks = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) trucks += m.draw_time_mean(rng).type_index == 1 ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(trucks) / n, 0.2, 0.01);
}

}  // namespace
}  // namespace entourage
