#pragma once
// Who is where: for each direction and lane, the vehicles in it ordered by progress along the
// direction of travel. A vehicle changing lanes is in both lanes. Built once per step from the
// world state (all owners and the ego) and queried for leaders and followers.
//
// Lane numbers of a direction: 0 .. lanes(dir) - 1 are its own lanes, 0 the rightmost. On a road
// with oncoming traffic a vehicle that overtakes uses the oncoming carriageway: lane
// lanes(dir) + j of its direction is the opposite direction's lane lanes(opp) - 1 - j (counting on
// to the left across the centre line). Each direction keeps the vehicles of its own direction in
// every slot; the vehicles of the other direction in the same physical lane are its oncoming
// traffic (oncoming()).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/ids.hpp"

namespace entourage {

class Fleet;

struct Occupant {
  VehicleId id = 0;
  double progress_m = 0.0;  // sign(direction) * s of the vehicle's centre
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
  double length_m = 0.0;
  int signal = 0;  // indicator on towards the lane to its left (+1) or right (-1), 0 off
  bool leaving = false;  // moving sideways out of this lane (the lane it is in until the move ends)
};

// The `signal` of an indicator (0 off, 1 left, 2 right).
inline int signal_of(std::uint8_t indicator) { return indicator == 1 ? 1 : indicator == 2 ? -1 : 0; }

class LaneIndex {
 public:
  LaneIndex(int lanes_forward, int lanes_backward);

  void clear();  // also forgets the drivers (drivers())
  void add(Direction dir, int lane, const Occupant& o);  // lanes outside the road are ignored
  void sort();  // call after the last add and before queries

  // Nearest vehicle ahead of / behind `progress_m` in the lane, skipping `self`. Ties in progress
  // are broken by id so that the answer is deterministic.
  const Occupant* leader(Direction dir, int lane, double progress_m, VehicleId self) const;
  const Occupant* follower(Direction dir, int lane, double progress_m, VehicleId self) const;
  // Both at once (one search).
  struct Neighbours {
    const Occupant* leader = nullptr;
    const Occupant* follower = nullptr;
  };
  Neighbours neighbours(Direction dir, int lane, double progress_m, VehicleId self) const;

  const std::vector<Occupant>& lane(Direction dir, int lane) const;
  // Position in lane(dir, lane) of the first occupant not behind (progress_m, id) in the index's
  // order (progress, then id): the std::lower_bound of that position.
  std::size_t first_not_behind(Direction dir, int lane, double progress_m, VehicleId id) const;
  int lanes(Direction dir) const;  // the direction's own lanes
  int slots(Direction dir) const;  // own lanes and the oncoming carriageway's

  // The same physical lane numbered from the opposite direction (-1 if it has none).
  int opposite_slot(Direction dir, int lane) const;
  // The nearest vehicle of the opposite direction ahead of `progress_m` (in `dir`'s sense) in the
  // physical lane `lane` of `dir`, coming towards it; nullptr if none. Its progress_m is in its
  // own direction's sense (use oncoming_gap()).
  const Occupant* oncoming(Direction dir, int lane, double progress_m) const;

  // The vehicles the service that built the index drives itself, whose drivers' own parameters
  // may be used for them (MOBIL's followers, lane_changes.cpp); null: none known (build_index
  // sets it; the fleet must outlive the index's use).
  // A copy or move of the index knows no drivers until it is built again: the fleet belongs to the
  // service object that built it (a copied core's index would point into the original's fleet).
  void set_drivers(const Fleet* fleet) { drivers_.fleet = fleet; }
  const Fleet* drivers() const { return drivers_.fleet; }

 private:
  std::vector<Occupant>* slot(Direction dir, int lane);

  struct NotCopied {
    const Fleet* fleet = nullptr;
    NotCopied() = default;
    NotCopied(const NotCopied& /*other*/) {}
    NotCopied& operator=(const NotCopied& /*other*/) {
      fleet = nullptr;
      return *this;
    }
  };
  NotCopied drivers_;
  int lanes_forward_;
  int lanes_backward_;
  std::vector<std::vector<Occupant>> forward_;
  std::vector<std::vector<Occupant>> backward_;
};

// Bumper-to-bumper gap from a follower to its leader.
inline double gap_between(const Occupant& leader, double follower_progress_m, double follower_length_m) {
  return leader.progress_m - follower_progress_m - 0.5 * (leader.length_m + follower_length_m);
}

// Front-to-front gap between a vehicle (progress in its own direction's sense) and an oncoming
// one found by LaneIndex::oncoming(), whose progress is in the opposite sense.
inline double oncoming_gap(const Occupant& oncoming, double progress_m, double length_m) {
  return -oncoming.progress_m - progress_m - 0.5 * (oncoming.length_m + length_m);
}

}  // namespace entourage
