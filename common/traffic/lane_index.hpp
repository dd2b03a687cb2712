#pragma once
// Who is where: for each direction and lane, the vehicles in it ordered by progress along the
// direction of travel. A vehicle changing lanes is in both lanes. Built once per step from the
// world state (all owners and the ego) and queried for leaders and followers.

#include <vector>

#include "core/ids.hpp"

namespace entourage {

struct Occupant {
  VehicleId id = 0;
  double progress_m = 0.0;  // sign(direction) * s of the vehicle's centre
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 0.0;
};

class LaneIndex {
 public:
  LaneIndex(int lanes_forward, int lanes_backward);

  void clear();
  void add(Direction dir, int lane, const Occupant& o);  // lanes outside the road are ignored
  void sort();  // call after the last add and before queries

  // Nearest vehicle ahead of / behind `progress_m` in the lane, skipping `self`. Ties in progress
  // are broken by id so that the answer is deterministic.
  const Occupant* leader(Direction dir, int lane, double progress_m, VehicleId self) const;
  const Occupant* follower(Direction dir, int lane, double progress_m, VehicleId self) const;

  const std::vector<Occupant>& lane(Direction dir, int lane) const;
  int lanes(Direction dir) const;

 private:
  std::vector<Occupant>* slot(Direction dir, int lane);

  std::vector<std::vector<Occupant>> forward_;
  std::vector<std::vector<Occupant>> backward_;
};

// Bumper-to-bumper gap from a follower to its leader.
inline double gap_between(const Occupant& leader, double follower_progress_m, double follower_length_m) {
  return leader.progress_m - follower_progress_m - 0.5 * (leader.length_m + follower_length_m);
}

}  // namespace entourage
