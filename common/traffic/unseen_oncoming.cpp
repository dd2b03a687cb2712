#include "traffic/unseen_oncoming.hpp"

#include "traffic/driving_environment.hpp"
#include "traffic/world.hpp"

namespace entourage {

UnseenOncoming unseen_oncoming(const ScenarioConfig& scenario) {
  UnseenOncoming u;
  const RoadConfig& road = scenario.road;
  const double flow_per_s = scenario.backward.flow_veh_per_s;
  if (!two_way_road(road) || !(flow_per_s > 0.0) || !(road.speed_limit_mps > 0.0)) return u;
  u.present = true;
  u.lanes = road.lanes_backward;
  u.speed_mps = road.speed_limit_mps;
  u.beyond_edge_m = road.speed_limit_mps / flow_per_s;
  return u;
}

void add_unseen_oncoming(LaneIndex& index, const UnseenOncoming& unseen, double front_edge_s_m) {
  if (!unseen.present) return;
  const double progress_m = -(front_edge_s_m + unseen.beyond_edge_m);  // backward: progress is -s
  for (int lane = 0; lane < unseen.lanes; ++lane) {
    add_to_index(index, Direction::kBackward, lane, lane, kUnseenOncomingFirstId + static_cast<VehicleId>(lane),
                 progress_m, unseen.speed_mps, 0.0, kUnseenOncomingLength_m);
  }
  index.sort();
}

}  // namespace entourage
