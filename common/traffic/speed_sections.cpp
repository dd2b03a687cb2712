#include "traffic/speed_sections.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
// Below this curvature a section is straight (as in road/road.cpp).
constexpr double kStraightCurvature = 1e-9;

// Every point along [0, length] where some condition may change.
std::vector<double> break_points_m(const RoadConfig& road, double length_m) {
  auto clip = [length_m](double s) { return std::clamp(s, 0.0, length_m); };
  std::vector<double> points{0.0, length_m};
  double s = 0.0;
  for (const auto& seg : road.segments) {
    s += seg.length_m;
    points.push_back(clip(s));
  }
  for (const auto& zone : road.speed_zones) {
    points.push_back(clip(zone.start_m));
    points.push_back(clip(zone.end_m));
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

// Curvature at s: that of the segment containing it, 0 past the last one (as Road does).
double curvature_at(const RoadConfig& road, double s_m) {
  double start = 0.0;
  for (const auto& seg : road.segments) {
    const double end = start + seg.length_m;
    if (s_m < end) return seg.curvature_per_m;
    start = end;
  }
  return 0.0;
}

// The limit at s: the last zone containing it overrides the road's (as Road::speed_limit_mps).
double limit_at(const RoadConfig& road, double s_m) {
  double limit = road.speed_limit_mps;
  for (const auto& zone : road.speed_zones) {
    if (s_m >= zone.start_m && s_m < zone.end_m) limit = zone.limit_mps;
  }
  return limit;
}

SectionConditions conditions_at(const RoadConfig& road, double s_m) {
  SectionConditions c;
  c.speed_limit_mps = limit_at(road, s_m);
  c.reference_limit_mps = road.speed_limit_mps;
  c.curvature_per_m = curvature_at(road, s_m);
  c.lane_width_m = road.lane_width_m;
  return c;
}

bool same_conditions(const SectionConditions& a, const SectionConditions& b) {
  return a.speed_limit_mps == b.speed_limit_mps && a.reference_limit_mps == b.reference_limit_mps &&
         a.curvature_per_m == b.curvature_per_m && a.lane_width_m == b.lane_width_m;
}

// True when the section leaves every driver at its basic desired speed.
bool reference_conditions(const SpeedAdaptationParams& p, const SectionConditions& c) {
  const bool limit_neutral =
      c.speed_limit_mps <= 0.0 || c.reference_limit_mps <= 0.0 || c.speed_limit_mps == c.reference_limit_mps;
  const bool straight = std::abs(c.curvature_per_m) < kStraightCurvature;
  const bool wide_enough = c.lane_width_m >= p.reference_lane_width_m;
  return limit_neutral && straight && wide_enough;
}
}  // namespace

SpeedSections::SpeedSections(const RoadConfig& road, const SpeedAdaptationParams& params) : params_(params) {
  const double length_m = std::max(0.0, road.length_m);
  const std::vector<double> points = break_points_m(road, length_m);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double start = points[i];
    const double end = points[i + 1];
    const SectionConditions c = conditions_at(road, 0.5 * (start + end));
    if (!sections_.empty() && same_conditions(sections_.back().conditions, c)) {
      sections_.back().end_m = end;
    } else {
      sections_.push_back({start, end, c});
    }
  }
  if (sections_.empty()) sections_.push_back({0.0, length_m, conditions_at(road, 0.0)});  // a road of length 0
  uniform_ = std::all_of(sections_.begin(), sections_.end(),
                         [this](const SpeedSection& sec) { return reference_conditions(params_, sec.conditions); });
}

const SpeedSection& SpeedSections::at(double s_m) const {
  auto it = std::upper_bound(sections_.begin(), sections_.end(), s_m,
                             [](double s, const SpeedSection& sec) { return s < sec.start_m; });
  if (it == sections_.begin()) return sections_.front();
  return *(it - 1);
}

double SpeedSections::local_desired_speed_mps(double s_m, double basic_desired_mps, double basic_median_mps) const {
  if (uniform_) return basic_desired_mps;
  return adapted_desired_speed_mps(params_, at(s_m).conditions, basic_desired_mps, basic_median_mps);
}

template <typename Visit>
void SpeedSections::for_each_ahead(Direction dir, double s_m, Visit visit) const {
  if (dir == Direction::kForward) {
    auto it = std::upper_bound(sections_.begin(), sections_.end(), s_m,
                               [](double s, const SpeedSection& sec) { return s < sec.start_m; });
    for (; it != sections_.end(); ++it) {
      if (!visit(*it, it->start_m - s_m)) return;
    }
  } else {
    auto it = std::lower_bound(sections_.begin(), sections_.end(), s_m,
                               [](const SpeedSection& sec, double s) { return sec.end_m < s; });
    while (it != sections_.begin()) {
      --it;
      if (!visit(*it, s_m - it->end_m)) return;
    }
  }
}

double SpeedSections::desired_speed_mps(Direction dir, double s_m, double basic_desired_mps,
                                        double basic_median_mps) const {
  if (uniform_) return basic_desired_mps;
  const double decel = params_.approach_decel_mps2;
  double v = local_desired_speed_mps(s_m, basic_desired_mps, basic_median_mps);
  // Looks at one section `distance_m` ahead; false once nothing further can lower v.
  for_each_ahead(dir, s_m, [&](const SpeedSection& sec, double distance_m) {
    if (approach_speed_mps(0.0, distance_m, decel) >= v) return false;
    const double v_section = adapted_desired_speed_mps(params_, sec.conditions, basic_desired_mps, basic_median_mps);
    v = std::min(v, approach_speed_mps(v_section, distance_m, decel));
    return true;
  });
  return v;
}

double SpeedSections::approach_decel_needed_mps2(Direction dir, double s_m, double speed_mps, double basic_desired_mps,
                                                 double basic_median_mps) const {
  if (uniform_ || speed_mps <= 0.0) return 0.0;
  // Beyond this distance even stopping needs less than approach_decel: nothing there matters.
  const double reach_m = speed_mps * speed_mps / (2.0 * params_.approach_decel_mps2);
  double needed = 0.0;
  for_each_ahead(dir, s_m, [&](const SpeedSection& sec, double distance_m) {
    if (distance_m > reach_m) return false;
    const double v_section = adapted_desired_speed_mps(params_, sec.conditions, basic_desired_mps, basic_median_mps);
    if (v_section < speed_mps) {
      needed = std::max(needed, (speed_mps * speed_mps - v_section * v_section) / (2.0 * std::max(distance_m, 1e-3)));
    }
    return true;
  });
  return needed;
}

}  // namespace entourage
