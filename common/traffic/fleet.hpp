#pragma once
// The vehicles a service owns, always in id order so that every phase iterates deterministically.

#include <algorithm>
#include <vector>

#include "traffic/actor_control.hpp"
#include "traffic/handoff.hpp"
#include "traffic/lane_index.hpp"
#include "traffic/vehicle.hpp"
#include "traffic/world.hpp"

namespace entourage {

class Fleet {
 public:
  // Takes ownership of the handoff's vehicle. A handoff older than `last_step` (a late message in
  // real time) is brought forward to last_step at constant speed, so nothing is lost.
  void adopt(const Handoff& h, Step last_step, double dt_s);
  bool owns(VehicleId id) const;
  Vehicle* find(VehicleId id);  // nullptr if not owned
  const Vehicle* find(VehicleId id) const;
  std::size_t size() const { return vehicles_.size(); }
  std::vector<Vehicle>& vehicles() { return vehicles_; }
  const std::vector<Vehicle>& vehicles() const { return vehicles_; }

  // Removes the vehicles for which `leaves` is true and returns them in id order.
  template <typename Pred>
  std::vector<Vehicle> extract_if(Pred leaves) {
    std::vector<Vehicle> out;
    auto first = std::find_if(vehicles_.begin(), vehicles_.end(), leaves);
    if (first == vehicles_.end()) return out;  // the usual step: nobody leaves, nothing moves
    auto kept = first;
    for (auto it = first; it != vehicles_.end(); ++it) {
      if (leaves(*it)) {
        out.push_back(std::move(*it));
      } else {
        if (kept != it) *kept = std::move(*it);
        ++kept;
      }
    }
    vehicles_.erase(kept, vehicles_.end());
    return out;
  }

 private:
  std::vector<Vehicle> vehicles_;
};

// Applies the handoffs addressed to `inbox`'s service (each exactly once) to the fleet, the state
// each carries brought forward to the step before `step` if it is late; returns how many joined
// (and their ids through `joined`, if given).
std::size_t adopt_handoffs(Fleet& fleet, HandoffInbox& inbox, std::vector<Handoff> handoffs, Step step, double dt_s,
                           std::vector<VehicleId>* joined = nullptr);

// A vehicle as the lane index holds it.
Occupant as_occupant(const Vehicle& v);

// Fills `index` with the fleet, every vehicle of the world that the fleet does not own (the
// world's copy of owned vehicles is the fleet's own state), and the ego; the fleet becomes the
// index's drivers (LaneIndex::drivers).
void build_index(LaneIndex& index, const Fleet& fleet, const std::vector<ObservedVehicle>& world,
                 const EgoObservation* ego);

// Gives each owned vehicle the control the director last wrote for it (commands are in vehicle
// id order; for one vehicle the later one wins). Commands for vehicles owned elsewhere are left
// to their owner. Returns how many were applied.
std::size_t apply_commands(Fleet& fleet, const std::vector<ActorCommand>& commands);

}  // namespace entourage
