// Road geometry: lanes, poses on straight and curved segments, speed zones.
#include <gtest/gtest.h>

#include <cmath>

#include "road/road.hpp"
#include "road/window.hpp"

namespace entourage {
namespace {

constexpr double kPi = 3.14159265358979323846;

RoadConfig two_plus_two() {
  RoadConfig c;
  c.length_m = 5000.0;
  c.lanes_forward = 2;
  c.lanes_backward = 2;
  c.lane_width_m = 3.5;
  c.median_width_m = 3.0;
  c.speed_limit_mps = 33.3;
  return c;
}

TEST(Road, LaneCentresRightOfTheLineForwardAndLeftBackward) {
  const Road r(two_plus_two());
  EXPECT_DOUBLE_EQ(r.lane_center_d(Direction::kForward, 1), -(1.5 + 1.75));
  EXPECT_DOUBLE_EQ(r.lane_center_d(Direction::kForward, 0), -(1.5 + 3.5 + 1.75));
  EXPECT_DOUBLE_EQ(r.lane_center_d(Direction::kBackward, 0), 1.5 + 3.5 + 1.75);
  for (Direction d : {Direction::kForward, Direction::kBackward}) {
    for (int lane : {0, 1}) EXPECT_EQ(r.lane_at(d, r.lane_center_d(d, lane)), lane);
  }
}

TEST(Road, StraightRoadPoses) {
  const Road r(two_plus_two());
  const Pose f = r.pose(100.0, -5.0, Direction::kForward);
  EXPECT_DOUBLE_EQ(f.x_m, 100.0);
  EXPECT_DOUBLE_EQ(f.y_m, -5.0);
  EXPECT_DOUBLE_EQ(f.heading_rad, 0.0);
  EXPECT_NEAR(std::abs(r.pose(100.0, 5.0, Direction::kBackward).heading_rad), kPi, 1e-12);
}

TEST(Road, QuarterCircleEndsWhereItShould) {
  RoadConfig c = two_plus_two();
  const double radius = 500.0;
  c.segments = {{100.0, 0.0}, {radius * kPi / 2.0, 1.0 / radius}, {1000.0, 0.0}};
  const Road r(c);
  const Pose end = r.pose(100.0 + radius * kPi / 2.0, 0.0, Direction::kForward);
  EXPECT_NEAR(end.x_m, 100.0 + radius, 1e-6);
  EXPECT_NEAR(end.y_m, radius, 1e-6);
  EXPECT_NEAR(end.heading_rad, kPi / 2.0, 1e-9);
  // a point to the right of the line is further from the centre of a left turn
  const Pose outer = r.pose(100.0 + radius * kPi / 4.0, -10.0, Direction::kForward);
  EXPECT_NEAR(std::hypot(outer.x_m - 100.0, outer.y_m - radius), radius + 10.0, 1e-6);
  EXPECT_DOUBLE_EQ(r.curvature_per_m(120.0), 1.0 / radius);
}

TEST(Road, SpeedZonesOverrideTheLimit) {
  RoadConfig c = two_plus_two();
  c.speed_zones = {{1000.0, 2000.0, 22.2}};
  const Road r(c);
  EXPECT_DOUBLE_EQ(r.speed_limit_mps(999.0), 33.3);
  EXPECT_DOUBLE_EQ(r.speed_limit_mps(1500.0), 22.2);
  EXPECT_DOUBLE_EQ(r.speed_limit_mps(2000.0), 33.3);
}

TEST(Window, RegionsAroundTheEgo) {
  const WindowConfig w{400.0, 200.0, 600.0, 400.0, 10.0};
  const WindowBounds b = WindowBounds::around(1000.0, w);
  EXPECT_EQ(b.region_of(399.0), Region::kOutside);
  EXPECT_EQ(b.region_of(400.0), Region::kOuterRear);
  EXPECT_EQ(b.region_of(799.0), Region::kOuterRear);
  EXPECT_EQ(b.region_of(800.0), Region::kInner);
  EXPECT_EQ(b.region_of(1400.0), Region::kInner);
  EXPECT_EQ(b.region_of(1401.0), Region::kOuterFront);
  EXPECT_EQ(b.region_of(2000.0), Region::kOuterFront);
  EXPECT_EQ(b.region_of(2001.0), Region::kOutside);
}

}  // namespace
}  // namespace entourage
