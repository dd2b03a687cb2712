#pragma once
// Drawing a driver for a new vehicle from its type's population (every draw from the caller's
// seeded stream), and building the vehicle itself.

#include "core/random.hpp"
#include "scenario/config.hpp"
#include "traffic/vehicle.hpp"

namespace entourage {

double draw(const NormalDist& d, Random& rng);

// The median of a truncated normal distribution (the mean when the truncation is symmetric).
double median_of(const NormalDist& d);

// A driver of `type` whose desired speed is `desired_speed_mps` (drawn by the caller, because
// where a vehicle enters decides which speeds are possible there). It is the basic desired speed,
// for the road's reference conditions (behaviour/speed_adaptation.hpp).
DriverParams draw_driver(const VehicleTypeConfig& type, double desired_speed_mps, std::uint64_t driver_seed,
                         Random& rng);

Vehicle make_vehicle(VehicleId id, std::uint8_t type_index, const VehicleTypeConfig& type, Direction dir, int lane,
                     double s_m, double speed_mps, const DriverParams& driver);

}  // namespace entourage
