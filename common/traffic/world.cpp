#include "traffic/world.hpp"

namespace entourage {

void add_to_index(LaneIndex& index, Direction dir, int lane, int target_lane, VehicleId id, double progress_m,
                  double speed_mps, double accel_mps2, double length_m, int signal) {
  Occupant o{id, progress_m, speed_mps, accel_mps2, length_m, signal, target_lane != lane};
  index.add(dir, lane, o);
  if (!o.leaving) return;
  o.leaving = false;  // the lane it moves into
  index.add(dir, target_lane, o);
}

void add_to_index(LaneIndex& index, const ObservedVehicle& v) {
  add_to_index(index, v.direction, v.lane, v.target_lane, v.id, v.progress_m(), v.speed_mps, v.accel_mps2,
               v.length_m, signal_of(v.indicator));
}

void add_to_index(LaneIndex& index, const EgoObservation& ego) {
  add_to_index(index, ego.direction, ego.lane, ego.target_lane, kEgoVehicleId, ego.progress_m(), ego.speed_mps,
               ego.accel_mps2, ego.length_m, signal_of(ego.indicator));
}

}  // namespace entourage
