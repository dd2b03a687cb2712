#include "traffic/lane_index.hpp"

#include <algorithm>

namespace entourage {

namespace {
bool before(const Occupant& a, const Occupant& b) {
  return a.progress_m < b.progress_m || (a.progress_m == b.progress_m && a.id < b.id);
}
const std::vector<Occupant> kEmptyLane;
}  // namespace

LaneIndex::LaneIndex(int lanes_forward, int lanes_backward)
    : lanes_forward_(std::max(0, lanes_forward)),
      lanes_backward_(std::max(0, lanes_backward)),
      forward_(static_cast<std::size_t>(lanes_forward_ + lanes_backward_)),
      backward_(static_cast<std::size_t>(lanes_forward_ + lanes_backward_)) {}

void LaneIndex::clear() {
  for (auto& l : forward_) l.clear();
  for (auto& l : backward_) l.clear();
}

std::vector<Occupant>* LaneIndex::slot(Direction dir, int lane) {
  auto& lanes = dir == Direction::kForward ? forward_ : backward_;
  if (lane < 0 || lane >= static_cast<int>(lanes.size())) return nullptr;
  return &lanes[static_cast<std::size_t>(lane)];
}

void LaneIndex::add(Direction dir, int lane, const Occupant& o) {
  if (auto* l = slot(dir, lane)) l->push_back(o);
}

void LaneIndex::sort() {
  for (auto& l : forward_) std::sort(l.begin(), l.end(), before);
  for (auto& l : backward_) std::sort(l.begin(), l.end(), before);
}

const std::vector<Occupant>& LaneIndex::lane(Direction dir, int lane) const {
  const auto& lanes = dir == Direction::kForward ? forward_ : backward_;
  if (lane < 0 || lane >= static_cast<int>(lanes.size())) return kEmptyLane;
  return lanes[static_cast<std::size_t>(lane)];
}

int LaneIndex::lanes(Direction dir) const { return dir == Direction::kForward ? lanes_forward_ : lanes_backward_; }

int LaneIndex::slots(Direction dir) const {
  return static_cast<int>(dir == Direction::kForward ? forward_.size() : backward_.size());
}

int LaneIndex::opposite_slot(Direction dir, int lane_no) const {
  const Direction opp = dir == Direction::kForward ? Direction::kBackward : Direction::kForward;
  const int own = lanes(dir);
  const int other = lanes(opp);
  if (lane_no < 0 || lane_no >= own + other) return -1;
  // Physical lanes numbered from dir's right edge: 0 .. own-1 its lanes, own .. own+other-1 the
  // opposite carriageway's, whose own numbering runs the other way.
  return own + other - 1 - lane_no;
}

const Occupant* LaneIndex::oncoming(Direction dir, int lane_no, double progress_m) const {
  const int opp_slot = opposite_slot(dir, lane_no);
  if (opp_slot < 0) return nullptr;
  const Direction opp = dir == Direction::kForward ? Direction::kBackward : Direction::kForward;
  // Ahead of us in our sense is behind -progress in theirs: the nearest is their follower there.
  return follower(opp, opp_slot, -progress_m, kNoVehicle);
}

const Occupant* LaneIndex::leader(Direction dir, int lane_no, double progress_m, VehicleId self) const {
  const auto& l = lane(dir, lane_no);
  const Occupant probe{self, progress_m, 0.0, 0.0, 0.0};
  auto it = std::upper_bound(l.begin(), l.end(), probe, before);
  for (; it != l.end(); ++it) {
    if (it->id != self) return &*it;
  }
  return nullptr;
}

const Occupant* LaneIndex::follower(Direction dir, int lane_no, double progress_m, VehicleId self) const {
  const auto& l = lane(dir, lane_no);
  const Occupant probe{self, progress_m, 0.0, 0.0, 0.0};
  auto it = std::lower_bound(l.begin(), l.end(), probe, before);
  while (it != l.begin()) {
    --it;
    if (it->id != self) return &*it;
  }
  return nullptr;
}

}  // namespace entourage
