#pragma once
// The window that moves with the ego (thesis ch. 3.2, papers I-II):
//
//   rear_edge      inner_rear           ego            inner_front      front_edge
//   |--- outer rear ---|------------ inner ------------|--- outer front ---|
//
// Regions are cut by road position s only, the same for both directions of travel.

#include "core/ids.hpp"
#include "scenario/config.hpp"

namespace entourage {

struct WindowBounds {
  double rear_edge_m = 0.0;
  double inner_rear_m = 0.0;
  double inner_front_m = 0.0;
  double front_edge_m = 0.0;

  static WindowBounds around(double ego_s_m, const WindowConfig& w) {
    WindowBounds b;
    b.inner_rear_m = ego_s_m - w.inner_behind_m;
    b.inner_front_m = ego_s_m + w.inner_ahead_m;
    b.rear_edge_m = b.inner_rear_m - w.outer_behind_m;
    b.front_edge_m = b.inner_front_m + w.outer_ahead_m;
    return b;
  }

  Region region_of(double s_m) const {
    if (s_m < rear_edge_m || s_m > front_edge_m) return Region::kOutside;
    if (s_m < inner_rear_m) return Region::kOuterRear;
    if (s_m > inner_front_m) return Region::kOuterFront;
    return Region::kInner;
  }

  bool in_inner(double s_m) const { return s_m >= inner_rear_m && s_m <= inner_front_m; }
};

}  // namespace entourage
