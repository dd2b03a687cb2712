#pragma once
// The play itself: once the actors are handed over, each role's actions run in the order listed,
// each when the previous one of its role has started and its own conditions hold (time since
// the handover, distance to the ego, the ego's time to collision with the actor). An action
// changes what the actor's control asks for: a speed (absolute, or relative to the ego's speed
// when it starts) at a rate, a lane change, an indicator.

#include <cstddef>
#include <vector>

#include "scenario/config.hpp"
#include "traffic/actor_control.hpp"
#include "traffic/world.hpp"

namespace entourage::director {

// The ego's time to collision with `actor` (along the ego's direction, whatever the lanes);
// infinite when they are not closing in.
double time_to_collision_s(const EgoObservation& ego, const ObservedVehicle& actor);

class Script {
 public:
  explicit Script(const PlayConfig& play);

  // Starts the actions due at `since_handover_s`; `actors[r]` is role r's vehicle (nullptr if not
  // seen this step) and `controls[r]` its control, changed in place. Returns how many started.
  std::size_t step(double since_handover_s, const EgoObservation& ego, const std::vector<const ObservedVehicle*>& actors,
                   std::vector<ActorControl>& controls, int lanes_of_ego_direction);

  std::size_t started() const { return started_; }

 private:
  bool due(const PlayActionConfig& a, double since_handover_s, const EgoObservation& ego, const ObservedVehicle& actor) const;

  PlayConfig play_;  // a copy: the play as staged at the handover
  std::vector<std::vector<std::size_t>> queue_;  // per role, the indices of its actions in order
  std::vector<std::size_t> next_;                // per role, position in its queue
  std::size_t started_ = 0;
};

}  // namespace entourage::director
