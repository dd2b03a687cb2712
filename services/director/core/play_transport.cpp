// The director's transport, a phase of a play's preparation (play.hpp): each actor is given the
// desired speed and lane that move it to its start (transport.hpp), under the floors its place
// in the ego's lane sets, and an actor that misses by far for a while is judged hopeless (its
// role is cast again: play_casting.cpp).
#include <algorithm>
#include <cmath>

#include "director/core/clearing.hpp"
#include "director/core/play.hpp"
#include "director/core/transport.hpp"

namespace entourage::director {

namespace {
// An actor whose plan misses its start by more than this many tolerances, or which is still in
// another lane this close to the start, for kHopelessFor_s (play.cpp), gives up its role.
constexpr double kHopelessMiss = 2.0;
constexpr double kLateLaneChange_s = 8.0;
// While the ego speeds up or slows down faster than this, the estimate swings with it (a driver
// who brakes is expected to go on braking for a while): no actor is judged hopeless then.
constexpr double kSteadyEgo_mps2 = 0.3;
// Nor while the ego drives below this share of its usual speed (its highest over the last
// kUsualSpeedWindow_s, play.cpp) with no leader it cannot pass (PlayRun::ego_slowed_down).
constexpr double kSlowedShare = 0.8;
}  // namespace

bool PlayRun::ego_slowed_down(const PlayInput& in) const {
  return in.ego.speed_mps < kSlowedShare * ego_usual_speed_.top() &&
         unpassable_leader(in.ego, in.world, setting_.lanes) == nullptr;
}

bool PlayRun::leaves_ego_lane_ahead(const PlayInput& in, const ObservedVehicle& actor, int start_lane) const {
  const int ego_lane = staged_lane(in);
  return actor.direction == in.ego.direction && start_lane != ego_lane && actor.lane == ego_lane &&
         sign(in.ego.direction) * (actor.s_m - in.ego.s_m) > 0.0;
}

double PlayRun::leaving_ego_lane_floor_mps(const PlayInput& in, const ObservedVehicle& actor, const Slot& slot,
                                           Role& role) const {
  if (!leaves_ego_lane_ahead(in, actor, slot.lane)) {
    role.leaving_floor_mps = -1.0;
  } else if (role.leaving_floor_mps < 0.0) {
    role.leaving_floor_mps = kSlowedShare * ego_usual_speed_.top();
  }
  return role.leaving_floor_mps < 0.0 ? -1.0 : std::min(role.leaving_floor_mps, in.ego.speed_mps);
}

void PlayRun::move_actors(const PlayInput& in, const std::vector<Slot>& slots, const Aim& aim, double time_to_start_s,
                          PlayOutput& out) {
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    Role& role = roles_[r];
    if (role.actor == kNoVehicle) continue;
    const ObservedVehicle* v = find(in, role.actor);
    if (v == nullptr) continue;  // a created vehicle not seen yet
    const double type_accel = accel_of(setting_.types, v->type_index);
    const double rate = transport_rate_mps2(setting_.director, type_accel);
    const Waypoint way = way_to(slots[r], aim, staged_.roles[r], in.ego.direction, staged_lane(in),
                                setting_.lanes, time_to_start_s, setting_.director);
    TransportCommand t = transport(way.slot, *v, way.time_s, role.command_mps, in.dt_s, in.world, in.ego,
                                   setting_.lanes, setting_.director, rate, type_accel);
    const PlayRoleConfig& rc = staged_.roles[r];
    const bool in_ego_lane = rc.direction == in.ego.direction && slots[r].lane == staged_lane(in) &&
                             v->lane == slots[r].lane && v->target_lane == v->lane;
    // The floors under its speed in the ego's lane (below 0: none): where it starts there, and
    // where it must leave it (the latter called at every step: it keeps its fixed part).
    double floor_mps = leaving_ego_lane_floor_mps(in, *v, slots[r], role);
    if (in_ego_lane) {
      const double ahead = sign(in.ego.direction) * (v->s_m - in.ego.s_m);
      floor_mps = std::max(floor_mps, rc.absolute_speed
                                          ? start_speed_floor_mps(ahead, rc.ahead_m, rc.position_tolerance_m, rc.speed_mps)
                                          : ego_pace_floor_mps(ahead, rc.ahead_m, in.ego.speed_mps, rc.speed_mps));
    }
    if (floor_mps > t.speed_mps) {
      t.speed_mps = floor_mps;
      t.drive_mps = drive_speed_mps(floor_mps, v->speed_mps, rate, type_accel);
    }
    // Never a wish above the highest of its type's drivers (as for the cleared vehicles,
    // play_clearing.cpp), unless the play asks its start speed above that: the desired speed given
    // to speed an actor up (drive_speed_mps) reached 181 km/h for cars that wish 150 at most.
    t.drive_mps = std::min(t.drive_mps, std::max(top_speed_of(setting_.types, v->type_index), slots[r].speed_mps));
    // Letting a cleared vehicle into its lane (let_in), it holds back below that one's speed.
    if (const ObservedVehicle* w = find(in, held_back_for(v->id))) {
      t.drive_mps = std::min(t.drive_mps, std::max(0.0, w->speed_mps - kLetIn_mps));
    }
    role.command_mps = t.speed_mps;
    role.position_error_m = t.position_error_m;
    role.speed_error_mps = t.speed_error_mps;
    const bool hopeless = std::abs(t.position_error_m) > kHopelessMiss * play_.roles[r].position_tolerance_m ||
                          (v->lane != slots[r].lane && v->target_lane != slots[r].lane && time_to_start_s < kLateLaneChange_s);
    if (!hopeless || std::abs(estimator_.smoothed_accel_mps2()) > kSteadyEgo_mps2 || ego_slowed_down(in)) {
      role.hopeless_since_s = -1.0;
    } else if (role.hopeless_since_s < 0.0) {
      role.hopeless_since_s = in.ego.time_s;
    }
    command(role.actor, transported(t.drive_mps, t.lane), in.step, out);
  }
}

}  // namespace entourage::director
