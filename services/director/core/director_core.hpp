#pragma once
// The event director (thesis ch. 3.1, papers III-IV): turns autonomous traffic into scripted
// plays at given places without the driver noticing. Each play runs on its own (play.hpp); the
// core gives them the step's world, keeps two plays from casting the same vehicle, makes the
// vehicles they create (ids from kDirectorFirstVehicleId, drivers drawn from the scenario's
// types with the director's own seeded stream) and hands those to meso.

#include <cstdint>
#include <vector>

#include "core/random.hpp"
#include "director/core/play.hpp"
#include "scenario/config.hpp"
#include "traffic/handoff.hpp"
#include "traffic/step_io.hpp"
#include "traffic/world.hpp"

namespace entourage::director {

struct DirectorOutput {
  std::vector<PlayReport> reports;
  std::vector<ActorCommand> commands;  // by play, then as decided
  std::vector<Handoff> births;         // vehicles created out of sight, handed to meso
};

class DirectorCore {
 public:
  DirectorCore(const ScenarioConfig& scenario, std::uint64_t seed);

  // The same inputs as the region cores (traffic/step_io.hpp): the ego at this step and every
  // vehicle published for the previous one, by id; the director uses no handoffs or commands.
  DirectorOutput step(const StepInput& in);
  const std::vector<PlayRun>& plays() const { return plays_; }

 private:
  class Factory : public VehicleFactory {
   public:
    Factory(const ScenarioConfig& scenario, std::uint64_t seed);
    double length_m(int type_index) const override;
    Vehicle make(int type_index, Direction dir, int lane, double s_m, double speed_mps) override;

   private:
    const ScenarioConfig& scenario_;
    std::uint64_t seed_;
    Random rng_;
    VehicleId next_id_ = kDirectorFirstVehicleId;
  };

  ScenarioConfig scenario_;
  Factory factory_;
  std::vector<PlayRun> plays_;
};

}  // namespace entourage::director
