#include "director/core/script.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace entourage::director {

double time_to_collision_s(const EgoObservation& ego, const ObservedVehicle& actor) {
  const int dir = sign(ego.direction);
  const double d = dir * (actor.s_m - ego.s_m);  // > 0: the actor is ahead
  const double gap = std::abs(d) - 0.5 * (actor.length_m + ego.length_m);
  const double u_actor = dir * sign(actor.direction) * actor.speed_mps;  // along the ego's direction
  const double closing = d > 0.0 ? ego.speed_mps - u_actor : u_actor - ego.speed_mps;
  if (closing <= 0.0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, gap) / closing;
}

Script::Script(const PlayConfig& play) : play_(play), queue_(play.roles.size()), next_(play.roles.size(), 0) {
  for (std::size_t i = 0; i < play.actions.size(); ++i) {
    queue_[static_cast<std::size_t>(play.actions[i].role)].push_back(i);
  }
}

bool Script::due(const PlayActionConfig& a, double since_handover_s, const EgoObservation& ego,
                 const ObservedVehicle& actor) const {
  if (since_handover_s + 1e-9 < a.at_s) return false;
  if (a.when_gap_below_m > 0.0 && std::abs(actor.s_m - ego.s_m) >= a.when_gap_below_m) return false;
  if (a.when_ttc_below_s > 0.0 && time_to_collision_s(ego, actor) >= a.when_ttc_below_s) return false;
  return true;
}

std::size_t Script::step(double since_handover_s, const EgoObservation& ego,
                         const std::vector<const ObservedVehicle*>& actors, std::vector<ActorControl>& controls,
                         int lanes_of_ego_direction) {
  std::size_t started = 0;
  for (std::size_t r = 0; r < queue_.size(); ++r) {
    const ObservedVehicle* actor = actors[r];
    if (actor == nullptr) continue;
    ActorControl& c = controls[r];
    while (next_[r] < queue_[r].size()) {
      const PlayActionConfig& a = play_.actions[queue_[r][next_[r]]];
      if (!due(a, since_handover_s, ego, *actor)) break;
      switch (a.kind) {
        case PlayActionKind::kSpeed:
          c.speed_mps = play_speed_mps(a.absolute_speed, a.speed_mps, ego.speed_mps);
          c.accel_mps2 = c.decel_mps2 = a.rate_mps2;
          break;
        case PlayActionKind::kLaneChange:
          c.lane = std::clamp(actor->lane + a.lane_offset, 0, std::max(0, lanes_of_ego_direction - 1));
          c.force_lane = !a.polite;
          c.lane_change_duration_s = a.duration_s;
          break;
        case PlayActionKind::kIndicator:
          c.indicator = a.indicator;
          break;
      }
      ++next_[r];
      ++started;
    }
  }
  started_ += started;
  return started;
}

}  // namespace entourage::director
