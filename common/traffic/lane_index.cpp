#include "traffic/lane_index.hpp"

#include <algorithm>

namespace entourage {

namespace {
// A function object, not a function pointer, so that sort and the searches inline it.
struct Before {
  bool operator()(const Occupant& a, const Occupant& b) const {
    return a.progress_m < b.progress_m || (a.progress_m == b.progress_m && a.id < b.id);
  }
};
constexpr Before before{};

const std::vector<Occupant> kEmptyLane;

// A lane is nearly in order from one step to the next (vehicles rarely pass within a lane), so an
// insertion sort is linear; it hands over to std::sort when the order turns out to be far off.
void sort_lane(std::vector<Occupant>& l) {
  const std::size_t budget = 4 * l.size() + 16;
  std::size_t moves = 0;
  for (std::size_t i = 1; i < l.size(); ++i) {
    if (!before(l[i], l[i - 1])) continue;
    if (moves > budget) {
      std::sort(l.begin(), l.end(), before);
      return;
    }
    const Occupant o = l[i];
    std::size_t j = i;
    for (; j > 0 && before(o, l[j - 1]); --j, ++moves) l[j] = l[j - 1];
    l[j] = o;
  }
}

}  // namespace

LaneIndex::LaneIndex(int lanes_forward, int lanes_backward)
    : lanes_forward_(std::max(0, lanes_forward)),
      lanes_backward_(std::max(0, lanes_backward)),
      forward_(static_cast<std::size_t>(lanes_forward_ + lanes_backward_)),
      backward_(static_cast<std::size_t>(lanes_forward_ + lanes_backward_)) {}

void LaneIndex::clear() {
  drivers_.fleet = nullptr;
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
  for (auto& l : forward_) sort_lane(l);
  for (auto& l : backward_) sort_lane(l);
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
  const Direction opp = opposite(dir);
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
  const Direction opp = opposite(dir);
  // Ahead of us in our sense is behind -progress in theirs: the nearest is their follower there.
  return follower(opp, opp_slot, -progress_m, kNoVehicle);
}

std::size_t LaneIndex::first_not_behind(Direction dir, int lane_no, double progress_m, VehicleId id) const {
  const auto& l = lane(dir, lane_no);
  // By progress alone (a plain comparison of doubles, the hot loop of the whole simulation), then
  // past the rare occupants at exactly the same progress with a smaller id.
  auto it = std::lower_bound(l.begin(), l.end(), progress_m,
                             [](const Occupant& a, double p) { return a.progress_m < p; });
  while (it != l.end() && it->progress_m == progress_m && it->id < id) ++it;
  return static_cast<std::size_t>(it - l.begin());
}

LaneIndex::Neighbours LaneIndex::neighbours(Direction dir, int lane_no, double progress_m, VehicleId self) const {
  const auto& l = lane(dir, lane_no);
  // Everything before `at` is behind the probe; from `at` on it is the probe itself or ahead.
  const auto at = l.begin() + static_cast<std::ptrdiff_t>(first_not_behind(dir, lane_no, progress_m, self));
  Neighbours n;
  for (auto it = at; it != l.end(); ++it) {
    if (it->id != self) {
      n.leader = &*it;
      break;
    }
  }
  for (auto it = at; it != l.begin();) {
    --it;
    if (it->id != self) {
      n.follower = &*it;
      break;
    }
  }
  return n;
}

const Occupant* LaneIndex::leader(Direction dir, int lane_no, double progress_m, VehicleId self) const {
  return neighbours(dir, lane_no, progress_m, self).leader;
}

const Occupant* LaneIndex::follower(Direction dir, int lane_no, double progress_m, VehicleId self) const {
  return neighbours(dir, lane_no, progress_m, self).follower;
}

}  // namespace entourage
