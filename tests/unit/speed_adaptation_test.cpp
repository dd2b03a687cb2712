// Speed adaptation (Brodin & Carlsson), the road's speed sections and what a driver knows of the
// road ahead, against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "behaviour/speed_adaptation.hpp"
#include "traffic/road_ahead.hpp"
#include "traffic/speed_sections.hpp"

namespace entourage {
namespace {

constexpr double kKmh = 1.0 / 3.6;

SectionConditions reference_conditions(double limit_mps) {
  SectionConditions c;
  c.speed_limit_mps = limit_mps;
  c.reference_limit_mps = limit_mps;
  c.curvature_per_m = 0.0;
  c.lane_width_m = 3.5;
  return c;
}

// ---- speed adaptation ------------------------------------------------------------------------

TEST(SpeedAdaptation, ReferenceConditionsLeaveEveryDriverAtItsBasicSpeed) {
  const SpeedAdaptationParams p;
  const SectionConditions c = reference_conditions(110.0 * kKmh);
  const SectionMedian m = section_median(p, c, 110.0 * kKmh);
  EXPECT_EQ(m.binding, SpeedFactor::kNone);
  EXPECT_DOUBLE_EQ(m.median_mps, 110.0 * kKmh);
  EXPECT_DOUBLE_EQ(m.rotation, 1.0);
  for (double v : {60.0, 110.0, 150.0}) EXPECT_DOUBLE_EQ(adapted_desired_speed_mps(p, c, v * kKmh, 110.0 * kKmh), v * kKmh);
}

TEST(SpeedAdaptation, LowerLimitShiftsAndRotatesTheDistribution) {
  const SpeedAdaptationParams p;  // limit_rotation 1.5
  SectionConditions c = reference_conditions(110.0 * kKmh);
  c.speed_limit_mps = 90.0 * kKmh;
  const SectionMedian m = section_median(p, c, 110.0 * kKmh);
  EXPECT_EQ(m.binding, SpeedFactor::kLimit);
  EXPECT_NEAR(m.median_mps, 90.0 * kKmh, 1e-12);
  EXPECT_DOUBLE_EQ(m.rotation, 1.5);
  const double r = 90.0 / 110.0;  // 0.818...
  // A 130 km/h driver: 90 + 20 * 0.818^1.5 = 104.80 km/h.
  const double v = adapted_desired_speed_mps(p, c, 130.0 * kKmh, 110.0 * kKmh);
  EXPECT_NEAR(v, (90.0 + 20.0 * std::pow(r, 1.5)) * kKmh, 1e-12);
  EXPECT_NEAR(v / kKmh, 104.80, 0.01);
  // The median driver gets the new median; a 70 km/h driver 90 - 40 * 0.740 = 60.40 km/h.
  EXPECT_NEAR(adapted_desired_speed_mps(p, c, 110.0 * kKmh, 110.0 * kKmh), 90.0 * kKmh, 1e-12);
  EXPECT_NEAR(adapted_desired_speed_mps(p, c, 70.0 * kKmh, 110.0 * kKmh) / kKmh, 60.40, 0.01);
  // rho > 1: the fast driver loses more than the median one (25.2 km/h against 20).
  EXPECT_GT(130.0 * kKmh - v, 20.0 * kKmh);
}

TEST(SpeedAdaptation, LowerLimitNeverMakesASlowDriverFaster) {
  const SpeedAdaptationParams p;
  SectionConditions c = reference_conditions(110.0 * kKmh);
  c.speed_limit_mps = 90.0 * kKmh;
  // Unclamped, a 20 km/h driver would get 90 - 90 * 0.740 = 23.4 km/h.
  const double unclamped = 90.0 - 90.0 * std::pow(90.0 / 110.0, 1.5);
  ASSERT_GT(unclamped, 20.0);
  EXPECT_DOUBLE_EQ(adapted_desired_speed_mps(p, c, 20.0 * kKmh, 110.0 * kKmh), 20.0 * kKmh);
  for (double v = 5.0; v <= 200.0; v += 5.0) {
    EXPECT_LE(adapted_desired_speed_mps(p, c, v * kKmh, 110.0 * kKmh), v * kKmh) << v << " km/h";
  }
}

TEST(SpeedAdaptation, NeverBelowTheMinimumDesiredSpeed) {
  SpeedAdaptationParams p;
  p.min_desired_speed_mps = 5.0;
  SectionConditions c = reference_conditions(30.0);
  c.speed_limit_mps = 6.0;  // m = 6 m/s, r = 0.2: a 10 m/s driver 6 - 20 * 0.2^1.5 = 4.2 m/s
  EXPECT_DOUBLE_EQ(adapted_desired_speed_mps(p, c, 10.0, 30.0), 5.0);
  // A driver already slower than the floor is not lifted to it.
  EXPECT_DOUBLE_EQ(adapted_desired_speed_mps(p, c, 4.0, 30.0), 4.0);
}

TEST(SpeedAdaptation, CurveOfRadius200AtTwoMetresPerSecondSquaredIs20MetresPerSecond) {
  const SpeedAdaptationParams p;  // a_lat 2, curve_rotation 2
  EXPECT_NEAR(curve_speed_mps(2.0, 1.0 / 200.0), 20.0, 1e-12);
  EXPECT_NEAR(curve_speed_mps(2.0, -1.0 / 200.0), 20.0, 1e-12);
  EXPECT_TRUE(std::isinf(curve_speed_mps(2.0, 0.0)));

  SectionConditions c = reference_conditions(25.0);
  c.curvature_per_m = -1.0 / 200.0;
  const SectionMedian m = section_median(p, c, 25.0);
  EXPECT_EQ(m.binding, SpeedFactor::kCurve);
  EXPECT_NEAR(m.median_mps, 20.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.rotation, 2.0);
  // r = 0.8: a 30 m/s driver 20 + 5 * 0.64 = 23.2 m/s.
  EXPECT_NEAR(adapted_desired_speed_mps(p, c, 30.0, 25.0), 23.2, 1e-12);
  // A gentle curve (median curve speed above the median) changes nothing.
  c.curvature_per_m = 1.0 / 2000.0;  // 63 m/s
  EXPECT_EQ(section_median(p, c, 25.0).binding, SpeedFactor::kNone);
}

TEST(SpeedAdaptation, TheLowestFactorBinds) {
  const SpeedAdaptationParams p;
  SectionConditions c = reference_conditions(25.0);
  c.speed_limit_mps = 22.0;         // m_limit 22
  c.curvature_per_m = 1.0 / 200.0;  // m_curve 20
  EXPECT_EQ(section_median(p, c, 25.0).binding, SpeedFactor::kCurve);
  c.speed_limit_mps = 15.0;  // m_limit 15
  const SectionMedian m = section_median(p, c, 25.0);
  EXPECT_EQ(m.binding, SpeedFactor::kLimit);
  EXPECT_NEAR(m.median_mps, 15.0, 1e-12);
}

TEST(SpeedAdaptation, NarrowLanesScaleEveryDriverWithRotationOne) {
  const SpeedAdaptationParams p;  // 0.08 per metre, rotation 1
  SectionConditions c = reference_conditions(25.0);
  c.lane_width_m = 3.0;  // 0.5 m narrower: m = 0.96 m_basic
  const SectionMedian m = section_median(p, c, 25.0);
  EXPECT_EQ(m.binding, SpeedFactor::kWidth);
  EXPECT_NEAR(m.median_mps, 24.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.rotation, 1.0);
  for (double v : {15.0, 25.0, 35.0}) EXPECT_NEAR(adapted_desired_speed_mps(p, c, v, 25.0), 0.96 * v, 1e-12);
  // Wider lanes than the reference do not raise speeds.
  c.lane_width_m = 4.0;
  EXPECT_EQ(section_median(p, c, 25.0).binding, SpeedFactor::kNone);
}

TEST(SpeedAdaptation, RaisedLimitRaisesSpeedsAndMakesNobodySlower) {
  const SpeedAdaptationParams p;
  SectionConditions c = reference_conditions(90.0 * kKmh);
  c.speed_limit_mps = 110.0 * kKmh;
  const SectionMedian m = section_median(p, c, 90.0 * kKmh);
  EXPECT_EQ(m.binding, SpeedFactor::kLimit);
  EXPECT_NEAR(m.median_mps, 110.0 * kKmh, 1e-12);
  const double r = 110.0 / 90.0;
  EXPECT_NEAR(adapted_desired_speed_mps(p, c, 100.0 * kKmh, 90.0 * kKmh), (110.0 + 10.0 * std::pow(r, 1.5)) * kKmh,
              1e-12);
  for (double v = 5.0; v <= 200.0; v += 5.0) {
    EXPECT_GE(adapted_desired_speed_mps(p, c, v * kKmh, 90.0 * kKmh), v * kKmh) << v << " km/h";
  }
  // A curve that asks for less than the raised median still binds.
  c.curvature_per_m = 1.0 / 450.0;  // 30 m/s, between 25 (basic) and 30.6 (raised)
  const SectionMedian mc = section_median(p, c, 25.0);
  EXPECT_EQ(mc.binding, SpeedFactor::kCurve);
  EXPECT_NEAR(mc.median_mps, 30.0, 1e-12);
}

TEST(SpeedAdaptation, NoLimitOrNoReferenceLimitMeansNoLimitFactor) {
  const SpeedAdaptationParams p;
  SectionConditions c = reference_conditions(0.0);
  EXPECT_EQ(section_median(p, c, 25.0).binding, SpeedFactor::kNone);
  c.speed_limit_mps = 20.0;  // reference 0
  EXPECT_EQ(section_median(p, c, 25.0).binding, SpeedFactor::kNone);
}

TEST(SpeedAdaptation, ApproachSpeed) {
  EXPECT_NEAR(approach_speed_mps(20.0, 100.0, 1.0), std::sqrt(400.0 + 200.0), 1e-12);
  EXPECT_DOUBLE_EQ(approach_speed_mps(20.0, 0.0, 1.0), 20.0);
  EXPECT_DOUBLE_EQ(approach_speed_mps(20.0, -50.0, 1.0), 20.0);
  EXPECT_NEAR(approach_speed_mps(0.0, 50.0, 1.0), 10.0, 1e-12);
}

// ---- speed sections --------------------------------------------------------------------------

// 3000 m at 25 m/s: straight 1000, a curve of radius 200 over [1000, 1500), straight to 2500,
// then no more segments (straight); a 20 m/s zone over [2000, 2600), and a zone at the road's own
// limit over [2900, 3500) that changes nothing.
RoadConfig sections_road() {
  RoadConfig r;
  r.length_m = 3000.0;
  r.speed_limit_mps = 25.0;
  r.lane_width_m = 3.5;
  r.segments = {{1000.0, 0.0}, {500.0, 1.0 / 200.0}, {1000.0, 0.0}};
  r.speed_zones = {{2000.0, 2600.0, 20.0}, {2900.0, 3500.0, 25.0}};
  return r;
}

TEST(SpeedSections, BoundariesMergeAndConditions) {
  const SpeedSections ss(sections_road(), SpeedAdaptationParams{});
  const auto& s = ss.sections();
  ASSERT_EQ(s.size(), 5u);
  const double starts[] = {0.0, 1000.0, 1500.0, 2000.0, 2600.0};
  const double ends[] = {1000.0, 1500.0, 2000.0, 2600.0, 3000.0};
  const double limits[] = {25.0, 25.0, 25.0, 20.0, 25.0};
  const double curvatures[] = {0.0, 1.0 / 200.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_DOUBLE_EQ(s[i].start_m, starts[i]) << i;
    EXPECT_DOUBLE_EQ(s[i].end_m, ends[i]) << i;
    EXPECT_DOUBLE_EQ(s[i].conditions.speed_limit_mps, limits[i]) << i;
    EXPECT_DOUBLE_EQ(s[i].conditions.reference_limit_mps, 25.0) << i;
    EXPECT_DOUBLE_EQ(s[i].conditions.curvature_per_m, curvatures[i]) << i;
    EXPECT_DOUBLE_EQ(s[i].conditions.lane_width_m, 3.5) << i;
  }
  EXPECT_FALSE(ss.uniform());
}

TEST(SpeedSections, AtFindsTheSectionAndClampsOutsideTheRoad) {
  const SpeedSections ss(sections_road(), SpeedAdaptationParams{});
  EXPECT_DOUBLE_EQ(ss.at(-10.0).start_m, 0.0);
  EXPECT_DOUBLE_EQ(ss.at(999.9).start_m, 0.0);
  EXPECT_DOUBLE_EQ(ss.at(1000.0).start_m, 1000.0);
  EXPECT_DOUBLE_EQ(ss.at(2599.0).start_m, 2000.0);
  EXPECT_DOUBLE_EQ(ss.at(3000.0).start_m, 2600.0);
  EXPECT_DOUBLE_EQ(ss.at(5000.0).start_m, 2600.0);
}

TEST(SpeedSections, LocalDesiredSpeed) {
  const SpeedSections ss(sections_road(), SpeedAdaptationParams{});
  // A median driver: 25 on the straights, 20 in the curve and in the 20 m/s zone.
  EXPECT_DOUBLE_EQ(ss.local_desired_speed_mps(500.0, 25.0, 25.0), 25.0);
  EXPECT_NEAR(ss.local_desired_speed_mps(1200.0, 25.0, 25.0), 20.0, 1e-12);
  EXPECT_NEAR(ss.local_desired_speed_mps(2300.0, 25.0, 25.0), 20.0, 1e-12);
  EXPECT_DOUBLE_EQ(ss.local_desired_speed_mps(2800.0, 25.0, 25.0), 25.0);
}

TEST(SpeedSections, ForwardDriverSlowsInTimeForTheCurve) {
  const SpeedSections ss(sections_road(), SpeedAdaptationParams{});  // approach decel 1
  // 100 m before the curve: sqrt(20^2 + 2 * 1 * 100).
  EXPECT_NEAR(ss.desired_speed_mps(Direction::kForward, 900.0, 25.0, 25.0), std::sqrt(600.0), 1e-12);
  // 300 m before: sqrt(1000) = 31.6 > 25, the curve does not matter yet.
  EXPECT_DOUBLE_EQ(ss.desired_speed_mps(Direction::kForward, 700.0, 25.0, 25.0), 25.0);
  // In the curve, the straight ahead does not raise it.
  EXPECT_NEAR(ss.desired_speed_mps(Direction::kForward, 1200.0, 25.0, 25.0), 20.0, 1e-12);
  // Past the curve, backward sections do not matter when driving forward.
  EXPECT_DOUBLE_EQ(ss.desired_speed_mps(Direction::kForward, 1600.0, 25.0, 25.0), 25.0);
  // 50 m before the zone: sqrt(400 + 100).
  EXPECT_NEAR(ss.desired_speed_mps(Direction::kForward, 1950.0, 25.0, 25.0), std::sqrt(500.0), 1e-12);
}

TEST(SpeedSections, BackwardDriverSlowsInTimeForTheZoneAndTheCurve) {
  const SpeedSections ss(sections_road(), SpeedAdaptationParams{});
  // Driving towards decreasing s, the zone ends at 2600: 100 m ahead of s = 2700.
  EXPECT_NEAR(ss.desired_speed_mps(Direction::kBackward, 2700.0, 25.0, 25.0), std::sqrt(600.0), 1e-12);
  // The curve ends at 1500: 100 m ahead of s = 1600.
  EXPECT_NEAR(ss.desired_speed_mps(Direction::kBackward, 1600.0, 25.0, 25.0), std::sqrt(600.0), 1e-12);
  // 100 m before the curve in the forward sense is behind a backward driver.
  EXPECT_DOUBLE_EQ(ss.desired_speed_mps(Direction::kBackward, 900.0, 25.0, 25.0), 25.0);
}

TEST(SpeedSections, LookAheadUsesTheDriversOwnSectionSpeed) {
  const SpeedAdaptationParams p;
  const SpeedSections ss(sections_road(), p);
  SectionConditions curve = reference_conditions(25.0);
  curve.curvature_per_m = 1.0 / 200.0;
  const double v_curve = adapted_desired_speed_mps(p, curve, 30.0, 25.0);  // 23.2
  EXPECT_NEAR(ss.desired_speed_mps(Direction::kForward, 950.0, 30.0, 25.0), std::sqrt(v_curve * v_curve + 100.0),
              1e-12);
}

TEST(SpeedSections, UniformRoadGivesTheBasicSpeedEverywhere) {
  RoadConfig r;
  r.length_m = 2000.0;
  r.speed_limit_mps = 25.0;
  r.segments = {{800.0, 0.0}, {1200.0, 0.0}};
  r.speed_zones = {{500.0, 700.0, 25.0}};  // the road's own limit
  const SpeedSections ss(r, SpeedAdaptationParams{});
  EXPECT_TRUE(ss.uniform());
  ASSERT_EQ(ss.sections().size(), 1u);
  EXPECT_DOUBLE_EQ(ss.sections()[0].end_m, 2000.0);
  for (double s : {0.0, 600.0, 1999.0}) {
    EXPECT_DOUBLE_EQ(ss.desired_speed_mps(Direction::kForward, s, 37.0, 25.0), 37.0);
    EXPECT_DOUBLE_EQ(ss.desired_speed_mps(Direction::kBackward, s, 12.0, 25.0), 12.0);
  }
  // Narrow lanes everywhere: no longer uniform.
  r.lane_width_m = 3.0;
  EXPECT_FALSE(SpeedSections(r, SpeedAdaptationParams{}).uniform());
}

// ---- road ahead ------------------------------------------------------------------------------

TEST(RoadAhead, StraightRoadHasUnlimitedSight) {
  RoadConfig r;
  r.length_m = 3000.0;
  r.segments = {{3000.0, 0.0}};
  const RoadAhead ahead(r);
  EXPECT_TRUE(std::isinf(ahead.sight_distance_m(Direction::kForward, 1000.0)));
  EXPECT_TRUE(std::isinf(ahead.sight_distance_m(Direction::kBackward, 1000.0)));
}

// A right-hand curve of radius 200 over [1000, 1500) and one of radius 1000 over [1500, 2000),
// clearance 5: chords sqrt(8000) = 89.4 and sqrt(40000) = 200.
RoadConfig curvy_road() {
  RoadConfig r;
  r.length_m = 3000.0;
  r.sight_clearance_m = 5.0;
  r.segments = {{1000.0, 0.0}, {500.0, -1.0 / 200.0}, {500.0, 1.0 / 1000.0}};
  return r;
}

TEST(RoadAhead, SightDistanceBeforeAndInsideACurve) {
  const RoadAhead ahead(curvy_road());
  const double chord200 = std::sqrt(8.0 * 200.0 * 5.0);
  const double chord1000 = std::sqrt(8.0 * 1000.0 * 5.0);
  // Forward, 200 m before the sharp curve (the gentle one gives 700 + 200).
  EXPECT_NEAR(ahead.sight_distance_m(Direction::kForward, 800.0), 200.0 + chord200, 1e-9);
  // Inside it.
  EXPECT_NEAR(ahead.sight_distance_m(Direction::kForward, 1200.0), chord200, 1e-9);
  // Inside the gentle one: the sharp one is behind.
  EXPECT_NEAR(ahead.sight_distance_m(Direction::kForward, 1700.0), chord1000, 1e-9);
  // Past both.
  EXPECT_TRUE(std::isinf(ahead.sight_distance_m(Direction::kForward, 2100.0)));
  // Backward from 2100: the gentle curve ends 100 m ahead (100 + 200), the sharp one 600 m ahead.
  EXPECT_NEAR(ahead.sight_distance_m(Direction::kBackward, 2100.0), 100.0 + chord1000, 1e-9);
  EXPECT_NEAR(ahead.sight_distance_m(Direction::kBackward, 1600.0), 100.0 + chord200, 1e-9);
  EXPECT_TRUE(std::isinf(ahead.sight_distance_m(Direction::kBackward, 900.0)));
}

TEST(RoadAhead, CurvesBeyondReachDoNotLimitSight) {
  RoadConfig r;
  r.length_m = 10000.0;
  r.segments = {{5000.0, 0.0}, {500.0, 1.0 / 200.0}};
  const RoadAhead ahead(r);
  EXPECT_TRUE(std::isinf(ahead.sight_distance_m(Direction::kForward, 0.0)));
  EXPECT_NEAR(ahead.sight_distance_m(Direction::kForward, 4000.0), 1000.0 + std::sqrt(8000.0), 1e-9);
}

RoadConfig restricted_road() {
  RoadConfig r;
  r.length_m = 3000.0;
  OvertakingRestrictionConfig forward_only;
  forward_only.start_m = 1000.0;
  forward_only.end_m = 1500.0;
  forward_only.backward = false;
  OvertakingRestrictionConfig backward_only;
  backward_only.start_m = 2000.0;
  backward_only.end_m = 2200.0;
  backward_only.forward = false;
  r.no_overtaking = {forward_only, backward_only};
  return r;
}

TEST(RoadAhead, RestrictionsApplyOnlyToTheirDirection) {
  const RoadAhead ahead(restricted_road());
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kForward, 500.0), 500.0);
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kForward, 1200.0), 0.0);
  // The backward-only zone is ignored: free to the road end.
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kForward, 1600.0), 1400.0);
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kBackward, 2500.0), 300.0);
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kBackward, 2100.0), 0.0);
  // The forward-only zone is ignored: free to s = 0.
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kBackward, 1800.0), 1800.0);
}

TEST(RoadAhead, RoadEndIsARestriction) {
  const RoadAhead ahead(restricted_road());
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kForward, 2900.0), 100.0);
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kForward, 3100.0), 0.0);
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kBackward, 50.0), 50.0);
  EXPECT_DOUBLE_EQ(ahead.restriction_free_m(Direction::kBackward, -10.0), 0.0);
}

RoadConfig closed_road() {
  RoadConfig r;
  r.length_m = 3000.0;
  r.lane_closures = {{Direction::kForward, 1, 1000.0, 1200.0}, {Direction::kBackward, 0, 500.0, 700.0}};
  return r;
}

TEST(RoadAhead, ForwardClosures) {
  const RoadAhead ahead(closed_road());
  EXPECT_DOUBLE_EQ(ahead.distance_to_closure_m(Direction::kForward, 1, 800.0), 200.0);
  EXPECT_DOUBLE_EQ(ahead.distance_to_closure_m(Direction::kForward, 1, 1100.0), 0.0);
  EXPECT_TRUE(std::isinf(ahead.distance_to_closure_m(Direction::kForward, 1, 1300.0)));
  EXPECT_TRUE(std::isinf(ahead.distance_to_closure_m(Direction::kForward, 0, 800.0)));
  // The backward closure is not in the forward lanes.
  EXPECT_TRUE(std::isinf(ahead.distance_to_closure_m(Direction::kForward, 0, 300.0)));
  EXPECT_FALSE(ahead.closed_within(Direction::kForward, 1, 800.0, 150.0));
  EXPECT_TRUE(ahead.closed_within(Direction::kForward, 1, 800.0, 200.0));
  EXPECT_TRUE(ahead.closed_within(Direction::kForward, 1, 1100.0, 0.0));
}

TEST(RoadAhead, BackwardClosures) {
  const RoadAhead ahead(closed_road());
  EXPECT_DOUBLE_EQ(ahead.distance_to_closure_m(Direction::kBackward, 0, 900.0), 200.0);
  EXPECT_DOUBLE_EQ(ahead.distance_to_closure_m(Direction::kBackward, 0, 600.0), 0.0);
  EXPECT_TRUE(std::isinf(ahead.distance_to_closure_m(Direction::kBackward, 0, 400.0)));
  EXPECT_TRUE(std::isinf(ahead.distance_to_closure_m(Direction::kBackward, 1, 900.0)));
  EXPECT_TRUE(std::isinf(ahead.distance_to_closure_m(Direction::kBackward, 1, 1300.0)));
  EXPECT_FALSE(ahead.closed_within(Direction::kBackward, 0, 900.0, 199.0));
  EXPECT_TRUE(ahead.closed_within(Direction::kBackward, 0, 900.0, 250.0));
}

}  // namespace
}  // namespace entourage
