#include "traffic/road_ahead.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
// Below this curvature a segment is straight (as in road/road.cpp): it does not limit sight.
constexpr double kStraightCurvature = 1e-9;
// Curves farther ahead than this do not limit the sight distance a driver judges from here.
constexpr double kSightReach_m = 2000.0;

// Distance from s to [start, end] in the direction of travel: 0 inside, negative if behind.
double distance_ahead_m(Direction dir, double s_m, double start_m, double end_m) {
  if (dir == Direction::kForward) {
    if (end_m <= s_m) return -1.0;
    return std::max(0.0, start_m - s_m);
  }
  if (start_m >= s_m) return -1.0;
  return std::max(0.0, s_m - end_m);
}

// The chord left visible inside a curve of radius R by a clearance c: sqrt(8 R c).
double sight_chord_m(double radius_m, double clearance_m) {
  return std::sqrt(8.0 * radius_m * std::max(0.0, clearance_m));
}
}  // namespace

RoadAhead::RoadAhead(const RoadConfig& road) : road_(road) {
  double start = 0.0;
  for (const auto& seg : road_.segments) {
    const double end = std::min(start + seg.length_m, road_.length_m);
    if (std::abs(seg.curvature_per_m) >= kStraightCurvature && end > start) {
      curves_.push_back({start, end, 1.0 / std::abs(seg.curvature_per_m)});
    }
    start += seg.length_m;
    if (start >= road_.length_m) break;
  }
}

double RoadAhead::sight_distance_m(Direction dir, double s_m) const {
  double sight = kUnlimited_m;
  for (const Curve& curve : curves_) {
    const double x = distance_ahead_m(dir, s_m, curve.start_m, curve.end_m);
    if (x < 0.0 || x > kSightReach_m) continue;
    sight = std::min(sight, x + sight_chord_m(curve.radius_m, road_.sight_clearance_m));
  }
  return sight;
}

double RoadAhead::restriction_free_m(Direction dir, double s_m) const {
  double free = dir == Direction::kForward ? road_.length_m - s_m : s_m;
  for (const auto& zone : road_.no_overtaking) {
    if (!zone.applies_to(dir)) continue;
    const double x = distance_ahead_m(dir, s_m, zone.start_m, zone.end_m);
    if (x >= 0.0) free = std::min(free, x);
  }
  return std::max(0.0, free);
}

double RoadAhead::distance_to_closure_m(Direction dir, int lane, double s_m) const {
  double distance = kUnlimited_m;
  for (const auto& closure : road_.lane_closures) {
    if (closure.direction != dir || closure.lane != lane) continue;
    const double x = distance_ahead_m(dir, s_m, closure.start_m, closure.end_m);
    if (x >= 0.0) distance = std::min(distance, x);
  }
  return distance;
}

bool RoadAhead::closed_within(Direction dir, int lane, double s_m, double distance_m) const {
  return distance_to_closure_m(dir, lane, s_m) <= distance_m;
}

}  // namespace entourage
