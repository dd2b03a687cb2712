#pragma once
// The oncoming traffic beyond the window's front edge. No service simulates it (the generator's
// front zone holds the ego's direction only), so a driver near the front edge who considered a
// pass in the oncoming lane of a two-way road saw that lane empty beyond the edge and passed as if
// it were: on the rural road, with a probe at the stream's speed, three times as many vehicles left
// the window ahead as the moving-observer relations say (45 against 15 an hour), and the window
// held 7 % fewer vehicles than the stream and carried 7 % less than the demand
// (services/generator/README.md, *The oncoming lane beyond the front edge*). The cores that drive
// the window's vehicles (micro, meso) add to their lane index one stand-in oncoming vehicle per
// oncoming lane, the oncoming demand's mean spacing beyond the edge (the speed limit over the
// flow), at the speed limit. Only those drivers' decisions see it; nobody publishes it.

#include "core/ids.hpp"
#include "scenario/config.hpp"
#include "traffic/lane_index.hpp"

namespace entourage {

// Ids of the stand-ins: kUnseenOncomingFirstId + lane (below kNoVehicle; the director's ids never
// reach them).
inline constexpr VehicleId kUnseenOncomingFirstId = 0xFFFFFF00u;
inline constexpr double kUnseenOncomingLength_m = 4.5;

struct UnseenOncoming {
  bool present = false;        // a two-way road with an oncoming demand
  int lanes = 0;               // oncoming lanes
  double beyond_edge_m = 0.0;  // the oncoming demand's mean spacing
  double speed_mps = 0.0;
};
UnseenOncoming unseen_oncoming(const ScenarioConfig& scenario);

// Adds the stand-ins beyond `front_edge_s_m` (the window's front edge, road s) and sorts the index.
void add_unseen_oncoming(LaneIndex& index, const UnseenOncoming& unseen, double front_edge_s_m);

}  // namespace entourage
