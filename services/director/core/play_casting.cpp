// The director's casting, a phase of a play's preparation (play.hpp): the roles still without an
// actor (or whose actor misses by far, or was left behind the ego by its lane change) are cast
// jointly (casting.hpp, cast_roles), a role no vehicle of the traffic can play gets a vehicle
// created out of the driver's sight (hidden_placement), and on one lane per direction, where there
// is no such place, the vehicle of the traffic that fits best (cheapest_fit).
#include <algorithm>
#include <string>
#include <vector>

#include "director/core/casting.hpp"
#include "director/core/play.hpp"

namespace entourage::director {

namespace {
// How long a role without an actor waits for a place to come free before a vehicle out of sight is
// taken off the road to make one (make_room).
constexpr double kRoomWait_s = 10.0;
}  // namespace

std::string PlayRun::cast(const PlayInput& in, const std::vector<Slot>& slots, const Aim& aim, double time_to_start_s,
                          const std::vector<bool>& restaged, PlayOutput& out) {
  const CastingSituation at{in.world,       in.ego,
                            aim.time_s,     aim.ego_s_m,
                            setting_.lanes, setting_.types,
                            zones_of(staged_, in.ego.direction, staged_lane(in), aim.ego_s_m, setting_.lanes),
                            opens_oncoming_gap(in)};
  // Only the roles still without an actor are cast; the others keep theirs. Each is cast for where
  // its way leads first (way_to: a cutter waits ahead of its start until the approach), as
  // move_actors will move it: cast or created for its start instead, a cutter from behind had
  // 20 s less and 50 m further to go, missed by far at once and was replaced after 3 s, again and
  // again.
  std::vector<std::size_t> open;
  std::vector<PlayRoleConfig> sub_roles;
  std::vector<Slot> sub_slots;
  std::vector<CastingSituation> sub_at;
  std::vector<bool> restaged_only;  // cast again only because it was restaged: nothing is created for it
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const bool due = this->open(roles_[r], in);
    if (!due && (restaged.empty() || !restaged[r])) continue;
    const Waypoint way = way_to(slots[r], aim, staged_.roles[r], in.ego.direction, staged_lane(in),
                                setting_.lanes, time_to_start_s, setting_.director);
    CastingSituation role_at = at;
    role_at.time_to_start_s = way.time_s;
    role_at.ego_s_at_handover_m = aim.ego_s_m - sign(in.ego.direction) * aim.ego_speed_mps * (aim.time_s - way.time_s);
    // A role whose start moved to the other side of the ego as the ego changed lanes keeps its
    // actor unless the actor would now have to get past the ego into the lane the ego is leaving
    // (stop 49: the cutter, cast in the left lane behind the ego, was left behind it when the ego
    // moved over, and in the 15-40 s left it could not get past the ego and the right lane's column).
    const ObservedVehicle* actor = find(in, roles_[r].actor);
    if (!due && (actor == nullptr || !passes_ego_to(way.slot, *actor, role_at))) continue;
    open.push_back(r);
    restaged_only.push_back(!due);
    sub_roles.push_back(play_.roles[r]);
    sub_slots.push_back(way.slot);
    sub_at.push_back(role_at);
  }
  // Vehicles this play cleared off the stage may be cast too (one in the way of an actor that
  // cannot get into its lane may be the better actor).
  std::vector<bool> castable = in.available;
  for (std::size_t i = 0; i < in.world.size(); ++i) {
    if (is_cleared(in.world[i].id)) castable[i] = true;
  }
  // Where each role would be created, found first: a creation behind the ego for a start ahead of
  // it in its lane costs more than one ahead (creation_cost_for). A restaged role keeps its actor
  // rather than have one created for it: it is cast again when it misses its start by far, as any
  // actor.
  const WindowBounds window = WindowBounds::around(in.ego.s_m, setting_.window);
  std::vector<std::optional<Placement>> places(open.size());
  std::vector<double> creation_costs(open.size());
  for (std::size_t k = 0; k < open.size(); ++k) {
    const int type = std::max(play_.roles[open[k]].type_index, 0);
    if (!restaged_only[k]) {
      places[k] = hidden_placement(sub_slots[k], in.factory.length_m(type), sub_at[k], window, setting_.director);
    }
    creation_costs[k] = creation_cost_for(places[k], setting_.director);
  }
  std::vector<int> chosen = cast_roles(sub_slots, sub_roles, castable, sub_at, setting_.director, creation_costs);
  std::string detail;
  for (std::size_t k = 0; k < open.size(); ++k) {
    Role& role = roles_[open[k]];
    const PlayRoleConfig& rc = play_.roles[open[k]];
    // An actor that gives its role up drives on as everyday traffic.
    auto replace = [&] {
      if (role.actor == kNoVehicle) return;
      command(role.actor, ActorControl{}, in.step, out);
      sent_.erase(role.actor);
    };
    const int type = std::max(rc.type_index, 0);
    const std::optional<Placement>& place = places[k];
    // Nowhere to create one on one lane per direction: the vehicle of the traffic that fits best,
    // if any, though a creation would have cost less (a truck of the traffic ahead of the ego, with
    // cars between that will pass it, leaves no place beyond it, and will not later). Where there
    // are more lanes a place is usually found a moment later (a freeway lead vehicle cast this way
    // instead held the ego up: seed 31, stop 43).
    if (chosen[k] < 0 && !place && setting_.lanes.of(sub_slots[k].direction) <= 1) {
      chosen[k] = cheapest_fit(sub_slots[k], sub_roles[k], castable, sub_at[k], chosen, setting_.director);
      // Not even that: a vehicle out of sight is taken off the road where a single one keeps a
      // place from being free, and the role is created there once it is gone.
      if (chosen[k] < 0) {
        const std::string made = make_room(in, role, sub_slots[k], in.factory.length_m(type), sub_at[k], window, out);
        if (!made.empty()) detail += (detail.empty() ? "" : ", ") + rc.name + ": " + made;
      }
    }
    if (chosen[k] >= 0) {
      replace();
      const ObservedVehicle& v = in.world[static_cast<std::size_t>(chosen[k])];
      in.available[static_cast<std::size_t>(chosen[k])] = false;
      cleared_.erase(std::remove(cleared_.begin(), cleared_.end(), v.id), cleared_.end());
      lane_requests_.erase(v.id);  // an actor now: its lane is the role's, not a clearing request
      role = Role{v.id, false, in.step, -1.0, 0.0, 0.0};
      detail += (detail.empty() ? "" : ", ") + rc.name + " = vehicle " + std::to_string(v.id);
      continue;
    }
    if (!place) continue;  // tried again at the next casting
    replace();
    Vehicle v = in.factory.make(type, sub_slots[k].direction, sub_slots[k].lane, place->s_m, place->speed_mps);
    v.control = transported(place->speed_mps, sub_slots[k].lane);
    sent_[v.id] = v.control;
    role = Role{v.id, true, in.step, place->speed_mps, 0.0, 0.0};
    ++created_count_;
    detail += (detail.empty() ? "" : ", ") + rc.name + " = new vehicle " + std::to_string(v.id) + " (" +
              to_string(place->region) + ")";
    out.created.push_back({std::move(v), place->region});
  }
  return detail;
}

std::string PlayRun::make_room(const PlayInput& in, Role& role, const Slot& slot, double length_m,
                               const CastingSituation& at, const WindowBounds& window, PlayOutput& out) {
  // Only for a role without an actor (one that misses by far keeps it until a better one is found),
  // once no place has come free for a while: one usually does as the traffic moves on (seed 32,
  // stop 56: 6 s after trigger point 1).
  if (role.actor != kNoVehicle) return {};
  if (role.unplaced_since_s < 0.0) role.unplaced_since_s = in.ego.time_s;
  if (in.ego.time_s - role.unplaced_since_s < kRoomWait_s) return {};
  if (making_room_ != kNoVehicle && find(in, making_room_) != nullptr) return {};
  making_room_ = kNoVehicle;
  const int i = blocker_to_take_off(slot, length_m, in.available, at, window, setting_.director);
  if (i < 0) return {};
  const auto index = static_cast<std::size_t>(i);
  making_room_ = in.world[index].id;
  in.available[index] = false;
  command(making_room_, withdrawn(), in.step, out);
  return "vehicle " + std::to_string(making_room_) + " taken off out of sight to make room";
}

}  // namespace entourage::director
