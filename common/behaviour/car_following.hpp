#pragma once
// Car-following models behind one interface: acceleration from the driver's parameters, its own
// speed and the leader it sees (if any). Models are picked by name through model_registry.hpp.

#include <cstdint>

#include "behaviour/idm.hpp"

namespace entourage {

enum class CarFollowingModel : std::uint8_t {
  kIdm = 0,          // Treiber et al. 2000
  kModifiedIdm = 1,  // IDM without interaction beyond beta s* (paper V; modified_idm.hpp)
};

struct CarFollowingParams {
  CarFollowingModel model = CarFollowingModel::kIdm;
  IdmParams idm;
  double beta = 1.35;  // modified IDM: interaction ends at gap = beta * s* (paper V)
};

struct LeaderView {
  double gap_m = 0.0;  // bumper to bumper
  double speed_mps = 0.0;
  double accel_mps2 = 0.0;
};

// Acceleration of a driver at `speed_mps`; `leader` null means a free road.
double car_following_accel_mps2(const CarFollowingParams& p, double speed_mps, const LeaderView* leader);

}  // namespace entourage
