#pragma once
// Road geometry: a reference line made of constant-curvature segments, with lanes on both sides.
// Positions are road coordinates (s along the reference line, d lateral, positive to the left of
// the forward direction); poses are world coordinates (x, y, heading) for the simulator.
//
// Lane layout (right-hand traffic): forward lanes lie right of the reference line, lane 0 the
// rightmost (outermost); backward lanes lie left of it, lane 0 again the rightmost as seen by
// their drivers. A median of median_width_m separates the directions.

#include <vector>

#include <Eigen/Core>

#include "core/ids.hpp"
#include "scenario/config.hpp"

namespace entourage {

struct Pose {
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_rad = 0.0;  // direction of travel
};

class Road {
 public:
  explicit Road(const RoadConfig& config);

  const RoadConfig& config() const { return config_; }
  double length_m() const { return config_.length_m; }
  int lanes(Direction dir) const { return config_.lanes(dir); }
  double lane_width_m() const { return config_.lane_width_m; }

  // Lateral offset of a lane's centre line; lanes >= lanes(dir) are the oncoming carriageway's
  // (lane lanes(dir) + j is the opposite direction's lane lanes(opp) - 1 - j).
  double lane_center_d(Direction dir, int lane) const;
  // The lane whose band contains d (clamped to the direction's lanes).
  int lane_at(Direction dir, double d_m) const;

  // World pose of a vehicle centre at (s, d) travelling in `dir`. s outside [0, length] is
  // extrapolated along the first or last segment.
  Pose pose(double s_m, double d_m, Direction dir) const;
  double curvature_per_m(double s_m) const;
  double speed_limit_mps(double s_m) const;

 private:
  struct SegmentStart {
    double s_m;
    double curvature_per_m;
    Eigen::Vector2d position;
    double heading_rad;
  };
  const SegmentStart& segment_at(double s_m) const;

  RoadConfig config_;
  std::vector<SegmentStart> segments_;
};

}  // namespace entourage
