#pragma once
// The services' pure cores wired together in one process, in lockstep, as the DDS shells wire
// them (common/dds/region_shell.hpp, services/ego/main.cpp), without DDS, threads or clocks: the
// ego stand-in, the generator, micro and one meso instance serving both outer regions.
//
// Step k: the ego moves to k seeing the world published for k-1; the generator, micro and meso
// each compute k from the same input (the ego at k and k-1, every vehicle published for k-1 in id
// order, the handoffs sent at k-1); what they publish is the world of k. Vehicle states and
// handoffs pass as the DDS messages carry them (common/dds/convert.cpp).

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "ego/core/ego_core.hpp"
#include "generator/core/generator_core.hpp"
#include "meso/core/meso_core.hpp"
#include "micro/core/micro_core.hpp"
#include "road/road.hpp"
#include "traffic/lateral.hpp"
#include "traffic/step_io.hpp"

namespace entourage::bench {

inline constexpr ServiceId kGeneratorService{Role::kGenerator, 0};
inline constexpr ServiceId kMicroService{Role::kMicro, 0};
inline constexpr ServiceId kMesoService{Role::kMeso, kMesoBoth};

// The generator's seed from the run's, as services/generator/main.cpp derives it.
inline std::uint64_t generator_seed(std::uint64_t run_seed) {
  return Random::derived(run_seed, static_cast<std::uint64_t>(Role::kGenerator)).next_u64();
}

// A vehicle state as the other services receive it (dds::to_msg, then dds::from_msg).
inline ObservedVehicle as_observed(const VehicleReport& r, ServiceId owner, Step step, const Road& road) {
  const Vehicle& v = r.vehicle;
  ObservedVehicle o;
  o.id = v.id;
  o.owner = owner;
  o.step = step;
  o.direction = v.direction;
  o.lane = v.lane;
  o.target_lane = v.target_lane();
  o.type_index = v.type_index;
  o.s_m = v.s_m;
  o.d_m = lateral_offset_m(road, v);
  o.speed_mps = v.speed_mps;
  o.accel_mps2 = v.accel_mps2;
  o.length_m = v.length_m;
  o.width_m = v.width_m;
  return o;
}

// A handoff as its receiver gets it: the message carries neither the overtaking state nor the
// HDM's memory of past decisions (dds::from_msg leaves them at their defaults).
inline Handoff as_received(Handoff h) {
  h.vehicle.overtaking = OvertakingState{};
  h.vehicle.hdm_memory = HdmMemory{};
  return h;
}

// What the three region-level cores computed for one step.
struct StepOutputs {
  StepOutput generator;
  StepOutput micro;
  StepOutput meso;
};

class WindowCores {
 public:
  WindowCores(const ScenarioConfig& scenario, std::uint64_t run_seed)
      : road_(scenario.road),
        ego_(scenario),
        generator_(scenario, generator_seed(run_seed)),
        micro_(scenario, kMicroService),
        meso_(scenario, kMesoService) {}

  // The input of the next step: the ego moved on (seeing the world of the previous step), the
  // world and the handoffs published at the previous step. Step 0 starts the run.
  StepInput next_input() {
    StepInput in;
    in.step = next_step_;
    if (next_step_ == 0) {
      in.ego = ego_.initial();
    } else {
      in.ego = ego_.step(next_step_, world_);
      in.ego_prev = ego_prev_;
      in.world_prev = world_;
      in.handoffs = handoffs_;
    }
    return in;
  }

  // Publishes what the cores computed for `in` as the world and handoffs of its step.
  void publish(const StepInput& in, const StepOutputs& out) {
    world_.clear();
    handoffs_.clear();
    add(out.generator, kGeneratorService, in.step);
    add(out.micro, kMicroService, in.step);
    add(out.meso, kMesoService, in.step);
    std::sort(world_.begin(), world_.end(),
              [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.id < b.id; });
    ego_prev_ = in.ego;
    ++next_step_;
  }

  generator::GeneratorCore& generator() { return generator_; }
  micro::MicroCore& micro() { return micro_; }
  meso::MesoCore& meso() { return meso_; }
  // Past the end of the road (with room for the window ahead): a run must stop here.
  bool at_road_end() const { return ego_.at_road_end(); }

 private:
  void add(const StepOutput& out, ServiceId owner, Step step) {
    for (const VehicleReport& r : out.states) world_.push_back(as_observed(r, owner, step, road_));
    for (const Handoff& h : out.handoffs) handoffs_.push_back(as_received(h));
  }

  Road road_;
  ego::EgoCore ego_;
  generator::GeneratorCore generator_;
  micro::MicroCore micro_;
  meso::MesoCore meso_;
  Step next_step_ = 0;
  EgoObservation ego_prev_;
  std::vector<ObservedVehicle> world_;  // published for the previous step, in id order
  std::vector<Handoff> handoffs_;       // sent at the previous step
};

}  // namespace entourage::bench
