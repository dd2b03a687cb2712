#include "director/core/director_core.hpp"

#include <algorithm>

#include "behaviour/model_registry.hpp"
#include "traffic/driver_draw.hpp"

namespace entourage::director {

namespace {
// Labels of the director's random streams (independent of every other service's).
constexpr std::uint64_t kDirectorStreamLabel = 0xD1EC7042ULL;
constexpr std::uint64_t kCreatedDriverLabel = 0xC2EA7EDULL;
}  // namespace

DirectorCore::Factory::Factory(const ScenarioConfig& scenario, std::uint64_t seed)
    : scenario_(scenario), seed_(seed), rng_(Random::derived(seed, kDirectorStreamLabel)) {}

double DirectorCore::Factory::length_m(int type_index) const {
  return scenario_.vehicle_types.at(static_cast<std::size_t>(type_index)).length_m;
}

Vehicle DirectorCore::Factory::make(int type_index, Direction dir, int lane, double s_m, double speed_mps) {
  const VehicleTypeConfig& type = scenario_.vehicle_types.at(static_cast<std::size_t>(type_index));
  const VehicleId id = next_id_++;
  const double desired = draw(type.driver.desired_speed_mps, rng_);
  const std::uint64_t driver_seed = Random::derived(seed_, kCreatedDriverLabel ^ id).next_u64();
  const DriverParams driver = draw_driver(type, desired, driver_seed, rng_);
  return make_vehicle(id, static_cast<std::uint8_t>(type_index), type, dir, lane, s_m, speed_mps, driver);
}

DirectorCore::DirectorCore(const ScenarioConfig& scenario, std::uint64_t seed)
    : scenario_(scenario), factory_(scenario_, seed) {
  TypeTable types;
  for (const VehicleTypeConfig& t : scenario_.vehicle_types) {
    types.push_back({t.driver.max_accel_mps2.mean,
                     lane_change_model_by_name(t.driver.lane_change) == LaneChangeModel::kOvertaking,
                     t.driver.desired_speed_mps.max});
  }
  const PlaySetting setting{scenario_.director, scenario_.window,
                            Lanes{scenario_.road.lanes_forward, scenario_.road.lanes_backward}, types};
  for (const PlayConfig& p : scenario_.plays) plays_.emplace_back(p, setting);
}

DirectorOutput DirectorCore::step(const StepInput& in) {
  DirectorOutput out;
  // A vehicle is free to cast unless it acts already (its owner publishes its control) or a
  // play holds it (its command may not have reached it yet).
  std::vector<VehicleId> held;
  for (const PlayRun& p : plays_) {
    for (VehicleId id : p.holds()) held.push_back(id);
  }
  std::sort(held.begin(), held.end());
  std::vector<bool> available(in.world_prev.size());
  for (std::size_t i = 0; i < in.world_prev.size(); ++i) {
    const ObservedVehicle& v = in.world_prev[i];
    available[i] = v.control == ControlMode::kAutonomous && !std::binary_search(held.begin(), held.end(), v.id);
  }
  const ServiceId self{Role::kDirector, 0};
  for (PlayRun& play : plays_) {
    PlayOutput po = play.step(PlayInput{in.step, scenario_.step_s, in.ego, in.world_prev, available, factory_});
    if (po.report) out.reports.push_back(std::move(*po.report));
    out.commands.insert(out.commands.end(), po.commands.begin(), po.commands.end());
    for (const PlayOutput::Created& c : po.created) {
      out.births.push_back(make_handoff(c.vehicle, in.step, self, Role::kMeso, c.region, HandoffReason::kDirector));
    }
  }
  return out;
}

}  // namespace entourage::director
