#pragma once
// The traffic just ahead of the window in the ego's direction. Vehicles slower than the window
// enter it from ahead; before the window's front edge reaches them they are simulated here, beyond
// the edge, owned by the generator and published like any vehicle (region "outside"), so that the
// window's vehicles near its front edge are held up by them as by the traffic ahead of them. Without
// them, the front-most vehicles of each lane had no leader, sped up to their desired speeds and
// left, and the window lost a third of its density in the ego's direction within minutes.
//
// A vehicle here drives at its stream speed (the speed it had in the observed stream; for one that
// left the window ahead, the speed the generator gives it: GeneratorCore::adopt_left_ahead), slowing
// only to keep a safe gap to whatever is ahead of it (a vehicle of the zone or of the window):
//
//   v_next = clamp(min(v_stream, v_leader + sqrt(2 b (gap - s0)), (gap - s0) / T),
//                  v - b_max dt, v + a dt), at least 0

#include <unordered_map>
#include <vector>

#include "traffic/fleet.hpp"
#include "traffic/lane_index.hpp"

namespace entourage::generator {

class FrontZone {
 public:
  // Adds a vehicle (id, lane, position and speed set); its present speed is its stream speed.
  void add(const Vehicle& v);
  // Adds a vehicle that will drive at `stream_speed_mps` (from its present speed, at its rates).
  void add(const Vehicle& v, double stream_speed_mps);
  // Moves every vehicle of the zone over one step, seeing the others (zone and window) in `index`.
  void move(const LaneIndex& index, double dt_s);
  // Removes and returns the vehicles the front edge (at progress `edge_m`) has reached.
  std::vector<Vehicle> reached_by(double edge_m);
  // Removes and returns the vehicles further ahead than `limit_m` (the ego slowed down: they will
  // not be reached).
  std::vector<Vehicle> beyond(double limit_m);
  // Removes and returns the vehicle `id` (if the zone has it).
  std::vector<Vehicle> remove(VehicleId id);

  // The director's commands to vehicles of the zone (a released actor or cleared vehicle that left
  // the window ahead): their control goes on with them into the window; the zone's own driving
  // does not look at it. Returns how many applied.
  std::size_t apply(const std::vector<ActorCommand>& commands) { return apply_commands(fleet_, commands); }

  const Fleet& vehicles() const { return fleet_; }
  bool owns(VehicleId id) const { return fleet_.owns(id); }

 private:
  Fleet fleet_;
  std::unordered_map<VehicleId, double> stream_speed_mps_;
};

}  // namespace entourage::generator
