#pragma once
// Lane changes within a direction's own lanes: MOBIL's discretionary changes (Kesting et al.
// 2007) and mandatory ones (the lane is closed ahead, or a play asks for a lane), each with the
// indicator on first and the lateral movement over time (thesis ch. 3.2).

#include "traffic/driving_environment.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

// MOBIL evaluation of a change from v.lane to `target` (no checks of timing or lane range), with
// the driver's car-following parameters `cf`.
struct LaneChangeOption {
  int target_lane = 0;
  bool safe = false;
  double advantage_mps2 = 0.0;
};
LaneChangeOption evaluate_lane_change(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                                      int target);
LaneChangeOption evaluate_lane_change(const Vehicle& v, const LaneIndex& index, int target);

// MOBIL judges the followers' accelerations (Kesting, Treiber & Helbing 2007) by each driver's own
// car-following model: that of vehicle `id` where the service that built the index drives it
// (LaneIndex::drivers), else `judge`, the deciding driver's own parameters (a vehicle driven by
// another service, or the ego).
const CarFollowingParams& model_of(VehicleId id, const LaneIndex& index, const CarFollowingParams& judge);

// The acceleration of `other` behind `leader` (null: a free road) by the base model `model`.
double follower_accel_mps2(const CarFollowingParams& model, const Occupant& other, const Occupant* leader);

// The lane `v` must move towards now (a closure of its lane ahead, or a requested lane), or -1.
int mandatory_target_lane(const Vehicle& v, const DrivingEnvironment& env);

// May `v` change into `lane` at its own choice (in range, not closed ahead, keep-right rule)?
bool lane_allowed(const Vehicle& v, int lane, const DrivingEnvironment& env);

struct LaneChangePlan {
  LaneChangeState state;
  bool mandatory = false;
};

// The next state of v's lane change (MOBIL or mandatory; none for drivers without lane changes).
// A vehicle the director moves calls off a signalled change it is no longer asked for.
LaneChangePlan plan_lane_change(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                                const DrivingEnvironment& env);

// A vehicle the director moves (transported) that waits, indicator on, to change into the lane it
// was asked for finds its gap by speed, as drivers do: it lets by the vehicle beside or just
// behind it in that lane that would leave it no safe gap in front even at that one's speed
// (dropping back to a little below that one's speed), unless that one signals towards its lane
// too or is slower than it, or brakes to below its speed within 2 s (holding back to let it in:
// the director's let-in); otherwise it eases in behind the vehicle ahead there (car following as
// if already in the lane). Never harder than its comfortable deceleration. Returns the cap on its
// acceleration (infinite when it is not seeking a gap).
// Without it a cleared vehicle drove beside a lane without gaps at the same speed until the play
// failed on it.
double gap_seeking_cap_mps2(const Vehicle& v, const CarFollowingParams& cf, const LaneIndex& index,
                            const LaneChangeState& lc);

// Starts the lateral movement from v.lane to `lane` over `duration_s` (no signalling phase).
LaneChangeState start_moving(const Vehicle& v, int lane, double duration_s);

}  // namespace entourage
