#pragma once
// Ownership changes (design invariant 1: one owner per live vehicle; ownership moves only by a
// handoff, applied at a step boundary, exactly once).
//
// A handoff carries the whole vehicle with its driver and a per-vehicle sequence number that
// grows by one at every change of owner. A receiver applies a handoff only if it is addressed to
// it and its sequence is newer than the last one it applied for that vehicle, so retransmitted or
// duplicated messages are dropped (and counted), never applied twice.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/ids.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

enum class HandoffReason : std::uint8_t {
  kBirth = 1,        // generated at a window edge
  kInitialFill = 2,  // generated when the window was filled
  kBorder = 3,       // crossed the border between inner and outer regions
  kLeftWindow = 4,   // beyond the window's edge: retired
  kDirector = 5,     // taken or released by the director
};

const char* to_string(HandoffReason r);

struct Handoff {
  Vehicle vehicle;  // vehicle.handoff_sequence is this handoff's sequence number
  Step step = 0;    // the step whose state the vehicle carries
  ServiceId from;
  Role to_role = Role::kNone;  // kNone: the vehicle is retired
  Region to_region = Region::kOutside;
  HandoffReason reason = HandoffReason::kBorder;
};

// Makes the handoff of `v` (state at `step`) and advances the vehicle's sequence number.
Handoff make_handoff(const Vehicle& v, Step step, ServiceId from, Role to_role, Region to_region,
                     HandoffReason reason);

// Is a handoff meant for a service of `role` serving `regions`?
bool addressed_to(const Handoff& h, Role role, const std::vector<Region>& regions);

// The receiving side of handoffs: decides which to apply, exactly once.
class HandoffInbox {
 public:
  HandoffInbox(Role role, std::vector<Region> regions) : role_(role), regions_(std::move(regions)) {}

  // Returns the handoffs to apply now, in a deterministic order (by step, then vehicle id), and
  // forgets duplicates. Handoffs not addressed to this service are ignored.
  std::vector<Handoff> accept(std::vector<Handoff> incoming);

  // Records that this service handed the vehicle on (so that an old duplicate of an earlier
  // handoff to us is not applied after the vehicle has left).
  void note_sent(const Handoff& h);

  std::uint64_t duplicates() const { return duplicates_; }

 private:
  Role role_;
  std::vector<Region> regions_;
  std::unordered_map<VehicleId, std::uint32_t> last_sequence_;
  std::uint64_t duplicates_ = 0;
};

}  // namespace entourage
