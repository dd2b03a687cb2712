#include "traffic/handoff.hpp"

#include <algorithm>

namespace entourage {

const char* to_string(HandoffReason r) {
  switch (r) {
    case HandoffReason::kBirth: return "birth";
    case HandoffReason::kInitialFill: return "initial_fill";
    case HandoffReason::kBorder: return "border";
    case HandoffReason::kLeftWindow: return "left_window";
    case HandoffReason::kDirector: return "director";
  }
  return "unknown";
}

Handoff make_handoff(const Vehicle& v, Step step, ServiceId from, Role to_role, Region to_region,
                     HandoffReason reason) {
  Handoff h;
  h.vehicle = v;
  h.vehicle.handoff_sequence = v.handoff_sequence + 1;
  h.step = step;
  h.from = from;
  h.to_role = to_role;
  h.to_region = to_region;
  h.reason = reason;
  return h;
}

bool addressed_to(const Handoff& h, Role role, const std::vector<Region>& regions) {
  if (h.to_role != role) return false;
  return std::find(regions.begin(), regions.end(), h.to_region) != regions.end();
}

std::vector<Handoff> HandoffInbox::accept(std::vector<Handoff> incoming) {
  std::sort(incoming.begin(), incoming.end(), [](const Handoff& a, const Handoff& b) {
    if (a.step != b.step) return a.step < b.step;
    if (a.vehicle.id != b.vehicle.id) return a.vehicle.id < b.vehicle.id;
    return a.vehicle.handoff_sequence < b.vehicle.handoff_sequence;
  });
  std::vector<Handoff> accepted;
  for (auto& h : incoming) {
    if (!addressed_to(h, role_, regions_)) continue;
    auto [it, inserted] = last_sequence_.try_emplace(h.vehicle.id, 0U);
    if (!inserted && h.vehicle.handoff_sequence <= it->second) {
      ++duplicates_;
      continue;
    }
    it->second = h.vehicle.handoff_sequence;
    accepted.push_back(std::move(h));
  }
  return accepted;
}

void HandoffInbox::note_sent(const Handoff& h) {
  auto& last = last_sequence_[h.vehicle.id];
  last = std::max(last, h.vehicle.handoff_sequence);
}

}  // namespace entourage
