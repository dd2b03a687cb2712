#include "traffic/fleet.hpp"

#include <algorithm>
#include <utility>

namespace entourage {

namespace {
bool by_id(const Vehicle& a, const Vehicle& b) { return a.id < b.id; }
}  // namespace

void Fleet::adopt(const Handoff& h, Step last_step, double dt_s) {
  Vehicle v = h.vehicle;
  if (h.step < last_step) {
    const double late_s = static_cast<double>(last_step - h.step) * dt_s;
    v.s_m += sign(v.direction) * v.speed_mps * late_s;
  }
  auto it = std::lower_bound(vehicles_.begin(), vehicles_.end(), v, by_id);
  if (it != vehicles_.end() && it->id == v.id) {
    *it = std::move(v);
  } else {
    vehicles_.insert(it, std::move(v));
  }
}

Vehicle* Fleet::find(VehicleId id) { return const_cast<Vehicle*>(std::as_const(*this).find(id)); }

const Vehicle* Fleet::find(VehicleId id) const {
  auto it = std::lower_bound(vehicles_.begin(), vehicles_.end(), id,
                             [](const Vehicle& v, VehicleId wanted) { return v.id < wanted; });
  return it != vehicles_.end() && it->id == id ? &*it : nullptr;
}

std::size_t apply_commands(Fleet& fleet, const std::vector<ActorCommand>& commands) {
  std::size_t n = 0;
  for (const ActorCommand& c : commands) {
    if (Vehicle* v = fleet.find(c.vehicle)) {
      v->control = c.control;
      ++n;
    }
  }
  return n;
}

bool Fleet::owns(VehicleId id) const { return find(id) != nullptr; }

std::size_t adopt_handoffs(Fleet& fleet, HandoffInbox& inbox, std::vector<Handoff> handoffs, Step step, double dt_s,
                           std::vector<VehicleId>* joined) {
  const Step last = step == 0 ? 0 : step - 1;
  std::size_t n = 0;
  for (const Handoff& h : inbox.accept(std::move(handoffs))) {
    fleet.adopt(h, last, dt_s);
    if (joined != nullptr) joined->push_back(h.vehicle.id);
    ++n;
  }
  return n;
}

Occupant as_occupant(const Vehicle& v) {
  return Occupant{v.id,       v.progress_m(), v.speed_mps, v.accel_mps2,
                  v.length_m, signal_of(static_cast<std::uint8_t>(v.indicator()))};
}

void build_index(LaneIndex& index, const Fleet& fleet, const std::vector<ObservedVehicle>& world,
                 const EgoObservation* ego) {
  index.clear();
  // Latest-created first: vehicles created earlier are further along, so the lanes come out
  // nearly in order of progress (cheap to sort).
  const auto& vehicles = fleet.vehicles();
  for (auto it = vehicles.rbegin(); it != vehicles.rend(); ++it) {
    const Vehicle& v = *it;
    add_to_index(index, v.direction, v.lane, v.target_lane(), v.id, v.progress_m(), v.speed_mps, v.accel_mps2,
                 v.length_m, signal_of(static_cast<std::uint8_t>(v.indicator())));
  }
  for (const auto& o : world) {
    if (!fleet.owns(o.id)) add_to_index(index, o);
  }
  if (ego != nullptr) add_to_index(index, *ego);
  index.sort();
  index.set_drivers(&fleet);
}

}  // namespace entourage
