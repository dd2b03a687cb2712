#pragma once
// Helpers shared by the region cores' unit tests (micro_core_test, meso_core_test): a car of the
// scenario's first type, its birth into a region, one step of a core in a standing world, and a
// core's published states as the world the next step sees.

#include <vector>

#include "traffic/driver_draw.hpp"
#include "traffic/handoff.hpp"
#include "traffic/step_io.hpp"
#include "traffic/world.hpp"

namespace entourage::testing {

inline constexpr ServiceId kGen{Role::kGenerator, 0};
inline constexpr ServiceId kMicroId{Role::kMicro, 0};
inline constexpr ServiceId kMesoId{Role::kMeso, 0};

inline Vehicle car(const ScenarioConfig& sc, VehicleId id, int lane, double s, double v, double v0) {
  Random rng(id);
  DriverParams d = draw_driver(sc.vehicle_types[0], v0, id, rng);
  return make_vehicle(id, 0, sc.vehicle_types[0], Direction::kForward, lane, s, v, d);
}

inline Handoff birth(const Vehicle& v, Role to, Region r) { return make_handoff(v, 0, kGen, to, r, HandoffReason::kBirth); }

// Runs a core with a standing world around it (the ego at a fixed place) and returns its output;
// `commands`: the director's, written at the previous step.
template <class Core>
StepOutput run_step(Core& core, Step k, const EgoObservation& ego, std::vector<Handoff> handoffs,
                    const std::vector<ObservedVehicle>& world, std::vector<ActorCommand> commands = {}) {
  StepInput in;
  in.step = k;
  in.ego = ego;
  in.ego_prev = ego;
  in.world_prev = world;
  in.handoffs = std::move(handoffs);
  in.commands = std::move(commands);
  return core.step(in);
}

inline std::vector<ObservedVehicle> as_world(const StepOutput& out, ServiceId owner) {
  std::vector<ObservedVehicle> w;
  for (const auto& r : out.states) {
    ObservedVehicle o;
    o.id = r.id;
    o.owner = owner;
    o.direction = r.direction;
    o.lane = r.lane;
    o.target_lane = r.target_lane;
    o.s_m = r.s_m;
    o.speed_mps = r.speed_mps;
    o.accel_mps2 = r.accel_mps2;
    o.length_m = r.length_m;
    w.push_back(o);
  }
  return w;
}

}  // namespace entourage::testing
