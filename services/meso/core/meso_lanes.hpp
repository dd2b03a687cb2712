#pragma once
// Lane choice in the outer regions: a cheap rule instead of MOBIL, so that a fast vehicle is not
// held for minutes behind a slightly slower one that, in real traffic, would have moved right
// or been passed. Only a blocked vehicle looks at the next lane:
//
//   pass     its gap-limited speed is below its desired speed by more than kBlockedSpeedLoss,
//            the lane to the left has room ahead (gap >= s0 + v T) and behind (the follower's
//            gap >= s0 + v_f T, and the follower would not brake harder than MOBIL's b_safe behind
//            it, by its own model where meso drives it), and its leader there is faster than the
//            present one
//   keep right  the lane to the right has room ahead for twice the safe gap, a leader there that
//            would not hold it up, and room behind
//
//   must     its lane is closed ahead (or a play asks for another lane): towards `must_target` as
//            soon as the lane there has room ahead and behind
//
//   call off a change just begun whose target lane has no room any more: the vehicle decided on
//            the world of the step before, and in that same step another service placed a vehicle
//            there (a birth at the window's edge) or another vehicle changed into it (between two
//            plans, only a vehicle that has just joined is checked: crowds_change). Only while
//            it has moved less than `call_off_fraction` of a lane sideways, so that going back is
//            invisible; beyond that it completes the change (micro's drivers signal first and
//            check again before moving, which closes the same race)
//
// A change then takes the driver's lane-change duration with the same lateral profile as in the
// inner region (the vehicle is in both lanes meanwhile), so a vehicle handed to micro mid-change
// continues it seamlessly.

#include <optional>

#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"

namespace entourage::meso {

struct LaneRules {
  double blocked_speed_loss_mps = 2.0;  // how much slower than desired counts as blocked
  double min_interval_s = 5.0;          // between the end of one change and the next
  double keep_right_gap_factor = 2.0;   // room wanted ahead in the right lane, in safe gaps
  double call_off_fraction = 0.02;      // a change is called off only before this share of the lateral move
};

// The lane `v` should start changing to now, if any. `must_target` (>= 0) is a lane it must move
// towards (traffic/lane_changes.hpp, mandatory_target_lane); -1 for none.
std::optional<int> choose_lane(const Vehicle& v, const LaneIndex& index, double gap_ahead_m, const LaneRules& rules,
                               int must_target = -1);

// Whether `v` calls off the lane change it has just begun (see "call off" above).
bool calls_off_change(const Vehicle& v, const LaneIndex& index, const LaneRules& rules);

// The same against one vehicle, without an index: whether `other`, in the lane `v`'s change has
// just begun towards (or moving into it), leaves `v` no room there. For the steps between two
// plans, when the vehicles that just joined (births at the window's edges, handoffs) are the only
// ones that can have taken that room (the others are seen at the plan).
bool crowds_change(const Vehicle& v, const Vehicle& other, const LaneRules& rules);

}  // namespace entourage::meso
