// The generator core: the window filled at the stream's density, arrivals at the edges at the
// moving-observer rates, never a vehicle on top of another.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core_test_util.hpp"
#include "generator/core/generator_core.hpp"
#include "road/window.hpp"
#include "traffic/stream.hpp"

namespace entourage::generator {
namespace {

using entourage::testing::ego_at;
using entourage::testing::freeway_scenario;

// Positions of all births of one direction and lane, to check spacing.
void expect_no_overlap(const std::vector<Handoff>& births, const EgoObservation& ego) {
  std::map<std::pair<int, int>, std::vector<std::pair<double, double>>> lanes;  // (dir, lane) -> (s, length)
  for (const auto& h : births) lanes[{sign(h.vehicle.direction), h.vehicle.lane}].push_back({h.vehicle.s_m, h.vehicle.length_m});
  lanes[{1, ego.lane}].push_back({ego.s_m, ego.length_m});
  for (auto& [key, v] : lanes) {
    std::sort(v.begin(), v.end());
    for (std::size_t i = 1; i < v.size(); ++i) {
      EXPECT_GT(v[i].first - v[i - 1].first, 0.5 * (v[i].second + v[i - 1].second))
          << "overlap in direction " << key.first << " lane " << key.second << " at s " << v[i].first;
    }
  }
}

TEST(Generator, InitialFillHasTheStreamsDensityAndNoOverlap) {
  const ScenarioConfig sc = freeway_scenario();
  for (std::uint64_t seed : {1ULL, 2ULL, 3ULL, 61ULL}) {
    GeneratorCore g(sc, seed);
    StepInput in;
    in.ego = ego_at(0, 5000.0, 30.5);
    const StepOutput out = g.step(in);
    const WindowBounds w = WindowBounds::around(5000.0, sc.window);
    const double length = w.front_edge_m - w.rear_edge_m;
    for (Direction d : {Direction::kForward, Direction::kBackward}) {
      const double expected = make_stream(sc, d).density_per_m() * length;
      const auto n = std::count_if(out.handoffs.begin(), out.handoffs.end(),
                                   [&](const Handoff& h) { return h.vehicle.direction == d; });
      EXPECT_NEAR(static_cast<double>(n), expected, 1.0) << "seed " << seed << " direction " << sign(d);
    }
    expect_no_overlap(out.handoffs, in.ego);
    for (const auto& h : out.handoffs) {
      EXPECT_EQ(h.reason, HandoffReason::kInitialFill);
      EXPECT_EQ(h.to_role, w.in_inner(h.vehicle.s_m) ? Role::kMicro : Role::kMeso);
      EXPECT_GE(h.vehicle.s_m, w.rear_edge_m);
      EXPECT_LE(h.vehicle.s_m, w.front_edge_m);
    }
  }
}

TEST(Generator, ArrivalsMatchTheMovingObserverRates) {
  const ScenarioConfig sc = freeway_scenario();
  GeneratorCore g(sc, 11);
  const double u = 30.0;
  const int steps = 36000;  // an hour
  std::map<std::pair<int, bool>, int> births;  // (direction, at the rear) -> count
  double s = 5000.0;
  for (int k = 0; k < steps; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, s, u);
    const StepOutput out = g.step(in);  // nothing ever moves: only the arrivals are counted
    for (const auto& h : out.handoffs) {
      if (h.reason != HandoffReason::kBirth) continue;
      EXPECT_NE(h.to_role, Role::kMicro) << "born inside the inner region";
      const bool rear = h.vehicle.s_m < s;
      ++births[{sign(h.vehicle.direction), rear}];
      if (h.vehicle.direction == Direction::kForward) {
        EXPECT_EQ(rear, h.vehicle.driver.desired_speed_mps() > u) << "fast ones from behind, slow ones from ahead";
      }
    }
    s += u * sc.step_s;
  }
  const double hours = steps * sc.step_s;
  const StreamModel fwd = make_stream(sc, Direction::kForward);
  const StreamModel bwd = make_stream(sc, Direction::kBackward);
  const auto within = [](int count, double expected) {
    return std::abs(count - expected) < 4.0 * std::sqrt(expected) + 2.0;  // Poisson, 4 sigma
  };
  const int fwd_rear = births[{1, true}];
  const int fwd_front = births[{1, false}];
  const int bwd_front = births[{-1, false}];
  const int bwd_rear = births[{-1, true}];
  EXPECT_TRUE(within(fwd_rear, fwd.rate_rear_per_s(u) * hours)) << fwd_rear;
  EXPECT_TRUE(within(fwd_front, fwd.rate_front_per_s(u) * hours)) << fwd_front;
  EXPECT_TRUE(within(bwd_front, bwd.rate_oncoming_per_s(u) * hours)) << bwd_front;
  EXPECT_EQ(bwd_rear, 0);
}

TEST(Generator, AStandingEgoGetsTheWholeFlowFromBehind) {
  const ScenarioConfig sc = freeway_scenario();
  GeneratorCore g(sc, 5);
  int rear = 0;
  int front_forward = 0;
  const int steps = 18000;
  for (int k = 0; k < steps; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, 5000.0, 0.0);
    for (const auto& h : g.step(in).handoffs) {
      if (h.reason != HandoffReason::kBirth || h.vehicle.direction != Direction::kForward) continue;
      (h.vehicle.s_m < 5000.0 ? rear : front_forward) += 1;
    }
  }
  const double expected = sc.forward.flow_veh_per_s * steps * sc.step_s;
  EXPECT_NEAR(rear, expected, 4.0 * std::sqrt(expected));
  EXPECT_EQ(front_forward, 0);
}

TEST(Generator, AJumpOfTheEgoRefillsTheWindow) {
  const ScenarioConfig sc = freeway_scenario();
  GeneratorCore g(sc, 9);
  StepInput in;
  in.ego = ego_at(0, 2000.0, 30.0);
  g.step(in);
  in.step = 1;
  in.ego = ego_at(1, 9000.0, 30.0);  // a simulator reset far down the road
  const StepOutput out = g.step(in);
  const auto fills = std::count_if(out.handoffs.begin(), out.handoffs.end(),
                                   [](const Handoff& h) { return h.reason == HandoffReason::kInitialFill; });
  EXPECT_GT(fills, 20);
  EXPECT_EQ(g.counters().fills, 2U);
}

TEST(Generator, SameSeedSameVehicles) {
  const ScenarioConfig sc = freeway_scenario();
  GeneratorCore a(sc, 77);
  GeneratorCore b(sc, 77);
  for (int k = 0; k < 300; ++k) {
    StepInput in;
    in.step = static_cast<Step>(k);
    in.ego = ego_at(in.step, 3000.0 + 30.0 * 0.1 * k, 30.0);
    const auto oa = a.step(in);
    const auto ob = b.step(in);
    ASSERT_EQ(oa.handoffs.size(), ob.handoffs.size());
    for (std::size_t i = 0; i < oa.handoffs.size(); ++i) {
      EXPECT_EQ(oa.handoffs[i].vehicle.id, ob.handoffs[i].vehicle.id);
      EXPECT_DOUBLE_EQ(oa.handoffs[i].vehicle.s_m, ob.handoffs[i].vehicle.s_m);
      EXPECT_DOUBLE_EQ(oa.handoffs[i].vehicle.driver.desired_speed_mps(), ob.handoffs[i].vehicle.driver.desired_speed_mps());
    }
  }
}

}  // namespace
}  // namespace entourage::generator
