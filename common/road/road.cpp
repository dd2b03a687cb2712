#include "road/road.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Below this curvature a segment is treated as straight (avoids dividing by ~0).
constexpr double kStraightCurvature = 1e-9;

double wrap_angle(double a) {
  while (a > kPi) a -= 2.0 * kPi;
  while (a <= -kPi) a += 2.0 * kPi;
  return a;
}

// Position and heading after travelling `ds` along an arc of curvature k from (p, heading).
void advance(const Eigen::Vector2d& p, double heading, double k, double ds, Eigen::Vector2d* out_p,
             double* out_heading) {
  if (std::abs(k) < kStraightCurvature) {
    *out_p = p + ds * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    *out_heading = heading;
    return;
  }
  const double h1 = heading + k * ds;
  *out_p = p + Eigen::Vector2d((std::sin(h1) - std::sin(heading)) / k,
                               (std::cos(heading) - std::cos(h1)) / k);
  *out_heading = h1;
}
}  // namespace

Road::Road(const RoadConfig& config) : config_(config) {
  Eigen::Vector2d p(0.0, 0.0);
  double heading = 0.0;
  double s = 0.0;
  for (const auto& seg : config_.segments) {
    segments_.push_back({s, seg.curvature_per_m, p, heading});
    advance(p, heading, seg.curvature_per_m, seg.length_m, &p, &heading);
    s += seg.length_m;
  }
  if (segments_.empty() || s < config_.length_m) {
    segments_.push_back({s, 0.0, p, heading});  // straight to the end of the road
  }
}

double Road::lane_center_d(Direction dir, int lane) const {
  if (lane >= lanes(dir)) {  // the oncoming carriageway (an overtaking vehicle)
    const Direction opp = opposite(dir);
    return lane_center_d(opp, lanes(opp) - 1 - (lane - lanes(dir)));
  }
  const double w = config_.lane_width_m;
  const double offset = 0.5 * config_.median_width_m + (lanes(dir) - lane - 0.5) * w;
  return dir == Direction::kForward ? -offset : offset;
}

int Road::lane_at(Direction dir, double d_m) const {
  const double w = config_.lane_width_m;
  const double from_median = (dir == Direction::kForward ? -d_m : d_m) - 0.5 * config_.median_width_m;
  const int lane = lanes(dir) - 1 - static_cast<int>(std::floor(from_median / w));
  return std::clamp(lane, 0, std::max(0, lanes(dir) - 1));
}

const Road::SegmentStart& Road::segment_at(double s_m) const {
  auto it = std::upper_bound(segments_.begin(), segments_.end(), s_m,
                             [](double s, const SegmentStart& seg) { return s < seg.s_m; });
  if (it == segments_.begin()) return segments_.front();
  return *(it - 1);
}

Pose Road::pose(double s_m, double d_m, Direction dir) const {
  const SegmentStart& seg = segment_at(s_m);
  Eigen::Vector2d p;
  double heading = 0.0;
  advance(seg.position, seg.heading_rad, seg.curvature_per_m, s_m - seg.s_m, &p, &heading);
  const Eigen::Vector2d left_normal(-std::sin(heading), std::cos(heading));
  p += d_m * left_normal;
  const double travel_heading = dir == Direction::kForward ? heading : heading + kPi;
  return Pose{p.x(), p.y(), wrap_angle(travel_heading)};
}

double Road::curvature_per_m(double s_m) const { return segment_at(s_m).curvature_per_m; }

double Road::speed_limit_mps(double s_m) const {
  double limit = config_.speed_limit_mps;
  for (const auto& zone : config_.speed_zones) {
    if (s_m >= zone.start_m && s_m < zone.end_m) limit = zone.limit_mps;
  }
  return limit;
}

}  // namespace entourage
