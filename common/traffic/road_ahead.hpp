#pragma once
// What a driver knows of the road ahead for overtaking and mandatory lane changes: how far the
// oncoming lane can be seen (curves hide it), how far the road is free of overtaking
// restrictions, and where its lane is closed. Built once from the scenario's road; all queries
// are in the direction of travel and return distances from s, >= 0 (infinity: nothing ahead).

#include <limits>
#include <vector>

#include "core/ids.hpp"
#include "scenario/config.hpp"

namespace entourage {

class RoadAhead {
 public:
  explicit RoadAhead(const RoadConfig& road);

  // Sight distance along the oncoming lane from s, travelling in `dir`. On a straight road it is
  // unlimited (infinity). From a curve of radius R (or when a curve starts x metres ahead) it is
  // x + sqrt(8 R c) with c = road.sight_clearance_m: the chord that the clearance inside the curve
  // leaves visible, using the sharpest curve within reach.
  double sight_distance_m(Direction dir, double s_m) const;

  // Distance from s to the first point ahead where overtaking is not allowed for `dir`: the start
  // of a no-overtaking zone (0 inside one), or the end of the road.
  double restriction_free_m(Direction dir, double s_m) const;

  // Distance from s to the start (in the direction of travel) of the next closure of `lane` of
  // `dir` (0 inside one; infinity if none ahead).
  double distance_to_closure_m(Direction dir, int lane, double s_m) const;

  // True if `lane` of `dir` is closed anywhere in [s, s + sign(dir) * distance_m].
  bool closed_within(Direction dir, int lane, double s_m, double distance_m) const;

 private:
  RoadConfig road_;
  struct Curve {
    double start_m;
    double end_m;
    double radius_m;
  };
  std::vector<Curve> curves_;  // sorted by start
};

inline constexpr double kUnlimited_m = std::numeric_limits<double>::infinity();

}  // namespace entourage
