#pragma once
// The services' pure cores wired together in one process, in lockstep, as the DDS shells wire
// them (common/dds/region_shell.hpp, services/ego/main.cpp), without DDS, threads or clocks: the
// ego stand-in, the generator, micro, one meso instance serving both outer regions, and the
// director (whose step a caller may skip when the scenario has no plays).
//
// Step k: the ego moves to k seeing the world published for k-1; the generator, micro and meso
// each compute k from the same input (the ego at k and k-1, every vehicle published for k-1 in id
// order, the handoffs sent at k-1); what they publish is the world of k. Vehicle states and
// handoffs pass as the DDS messages carry them (common/dds/convert.cpp).

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "dds/convert.hpp"
#include "director/core/director_core.hpp"
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

// A vehicle state, a handoff and a command as their receivers get them: through the messages
// the DDS shells send (common/dds/convert.cpp), so whatever a message does not carry is lost here
// too (e.g. the overtaking state and the HDM's memory of a handed-over vehicle).
inline ObservedVehicle as_observed(const VehicleReport& r, ServiceId owner, Step step, double time_s, const Road& road) {
  return dds::from_msg(dds::to_msg(r, owner, step, time_s, road));
}
inline Handoff as_received(const Handoff& h, double time_s, const Road& road) {
  return dds::from_msg(dds::to_msg(h, time_s, road));
}
inline ActorCommand as_received(const ActorCommand& c, double time_s) { return dds::from_msg(dds::to_msg(c, time_s)); }

// What the cores computed for one step.
struct StepOutputs {
  StepOutput generator;
  StepOutput micro;
  StepOutput meso;
  director::DirectorOutput director;
};

class WindowCores {
 public:
  WindowCores(const ScenarioConfig& scenario, std::uint64_t run_seed)
      : road_(scenario.road),
        ego_(scenario, run_seed),
        generator_(scenario, generator_seed(run_seed)),
        micro_(scenario, kMicroService),
        meso_(scenario, kMesoService),
        director_(scenario, run_seed),
        step_s_(scenario.step_s) {}

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
      in.commands = commands_;
    }
    return in;
  }

  // The director's step for `in` (it sees the same ego and world as the region cores).
  director::DirectorOutput direct(const StepInput& in) { return director_.step(in); }

  // Every core's step for `in`, in the order the lockstep runs them.
  StepOutputs compute(const StepInput& in) {
    StepOutputs out;
    out.generator = generator_.step(in);
    out.micro = micro_.step(in);
    out.meso = meso_.step(in);
    out.director = direct(in);
    return out;
  }

  // Publishes what the cores computed for `in` as the world and handoffs of its step.
  void publish(const StepInput& in, const StepOutputs& out) {
    world_.clear();
    handoffs_.clear();
    commands_.clear();
    const double time_s = static_cast<double>(in.step) * step_s_;
    add(out.generator, kGeneratorService, in.step, time_s);
    add(out.micro, kMicroService, in.step, time_s);
    add(out.meso, kMesoService, in.step, time_s);
    for (const Handoff& h : out.director.births) handoffs_.push_back(as_received(h, time_s, road_));
    for (const ActorCommand& c : out.director.commands) commands_.push_back(as_received(c, time_s));
    std::stable_sort(commands_.begin(), commands_.end(),
                     [](const ActorCommand& a, const ActorCommand& b) { return a.vehicle < b.vehicle; });
    std::sort(world_.begin(), world_.end(),
              [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.id < b.id; });
    ego_prev_ = in.ego;
    ++next_step_;
  }

  generator::GeneratorCore& generator() { return generator_; }
  micro::MicroCore& micro() { return micro_; }
  meso::MesoCore& meso() { return meso_; }
  director::DirectorCore& director() { return director_; }
  const std::vector<ObservedVehicle>& world() const { return world_; }
  // Past the end of the road (with room for the window ahead): a run must stop here.
  bool at_road_end() const { return ego_.at_road_end(); }

 private:
  void add(const StepOutput& out, ServiceId owner, Step step, double time_s) {
    for (const VehicleReport& r : out.states) world_.push_back(as_observed(r, owner, step, time_s, road_));
    for (const Handoff& h : out.handoffs) handoffs_.push_back(as_received(h, time_s, road_));
  }

  Road road_;
  ego::EgoCore ego_;
  generator::GeneratorCore generator_;
  micro::MicroCore micro_;
  meso::MesoCore meso_;
  director::DirectorCore director_;
  double step_s_;
  Step next_step_ = 0;
  EgoObservation ego_prev_;
  std::vector<ObservedVehicle> world_;  // published for the previous step, in id order
  std::vector<Handoff> handoffs_;       // sent at the previous step
  std::vector<ActorCommand> commands_;  // written by the director at the previous step
};

}  // namespace entourage::bench
