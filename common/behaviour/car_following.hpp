#pragma once
// Car-following models behind one interface: acceleration from the driver's parameters, its own
// speed and the leader it sees (if any). Models are picked by name through model_registry.hpp;
// the Human Driver Model wraps IDM or the modified IDM (hdm.hpp, used by traffic/driving.hpp,
// which knows the further leaders and the driver's state).

#include <cstdint>

#include "behaviour/gipps.hpp"
#include "behaviour/hdm_params.hpp"
#include "behaviour/idm.hpp"
#include "behaviour/leader_view.hpp"

namespace entourage {

enum class CarFollowingModel : std::uint8_t {
  kIdm = 0,          // Treiber et al. 2000
  kModifiedIdm = 1,  // IDM without interaction beyond beta s* (paper V; modified_idm.hpp)
  kGipps = 2,        // Gipps 1981 (gipps.hpp)
};

struct CarFollowingParams {
  CarFollowingModel model = CarFollowingModel::kIdm;
  IdmParams idm;
  double beta = 1.35;  // modified IDM: interaction ends at gap = beta * s* (paper V)
  // IDM and the modified IDM: the ACC model's coolness (cah.hpp, Kesting et al. 2010), blending in
  // the constant-acceleration heuristic where IDM would brake harder; 0 = off (the base model).
  double coolness = 0.0;
  GippsParams gipps;
  // The Human Driver Model around IDM or the modified IDM (hdm.hpp): reaction time, estimation
  // errors, several anticipated leaders. Off: the base model alone.
  bool human_driver = false;
  HdmParams hdm;
};

// Acceleration of a driver at `speed_mps` behind one leader, as the base model gives it (without
// the HDM's errors, delay and further leaders); `leader` null means a free road.
double car_following_accel_mps2(const CarFollowingParams& p, double speed_mps, const LeaderView* leader);

}  // namespace entourage
