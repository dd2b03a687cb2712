#include "director/core/casting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "director/core/assignment.hpp"
#include "director/core/zones.hpp"

namespace entourage::director {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// A new vehicle's place is searched in steps of this much around the ideal one.
constexpr double kPlacementStep_m = 20.0;
constexpr int kPlacementTries = 20;
// Created vehicles are kept this far inside the window's edges (so they are not retired at once).
constexpr double kEdgeMargin_m = 30.0;
// Safe gap for a created vehicle to its neighbours: standstill distance plus a time gap.
constexpr double kPlacementStandstill_m = 5.0;
constexpr double kPlacementTimeGap_s = 1.5;
// While the ideal place is still beyond the window's edge (it comes within the window later), a
// vehicle is only created where it needs at most this share of the transport band's offset to
// reach its start in time: the rest is left for the corrections the estimate's changes ask for.
// (Created early at the window's edge, an oncoming actor had to wait at the band's low edge, and
// when the ego slowed in the last seconds it could not wait any longer and came too early.)
constexpr double kEarlyCreationSpeedShare = 0.5;

// A vehicle whose best plan misses the slot by up to this share of the role's tolerance may
// still be cast (re-planning on the way closes most of it).
constexpr double kCastingSlack = 0.5;
// A vehicle that never overtakes, ahead of the ego on one lane per direction, stays between the ego
// and any other vehicle or place ahead of it (stuck_between): where it fits the role it is the one
// actor possible, and is cast up to this many tolerances off (as far as an actor may miss before
// it gives up, play_transport.cpp, kHopelessMiss). Otherwise the role had no actor at all: a truck of the
// traffic 685 m ahead of the ego at trigger point 1 missed by 17 m, the next second by more
// (slow truck, seed 6, stop 43).
constexpr double kBlockerSlack = 2.0;

bool type_fits(const PlayRoleConfig& role, const ObservedVehicle& v) {
  return role.type_index < 0 || role.type_index == static_cast<int>(v.type_index);
}

// The extra speed change a creation is worth: a fitting vehicle of the traffic is preferred
// unless it would have to change its speed by more than the transport band allows anyway.
double creation_cost(const DirectorConfig& cfg) { return cfg.max_speed_offset_mps; }

// A vehicle that must get past the ego to a slot in the ego's lane needs the ego's speed to be
// left behind and a gap ahead of the ego to come back in, neither of which the director controls.
bool passes_ego_into_its_lane(const Slot& slot, const Between& b, const CastingSituation& at) {
  return b.ego && occupies(at.ego, slot.direction, slot.lane);
}

// The vehicles of the slot's lane (and the ego) too near a vehicle of length `length_m` created at
// `s_m` at `speed_mps`: closer than a standstill distance and a time gap at the follower's speed.
// Counted up to `limit` (the search stops there): how many, and the world index of the first
// vehicle found (-1 where the first is the ego, or there is none).
struct Blockers {
  int count = 0;
  int first = -1;
};
Blockers place_blockers(const Slot& slot, double s_m, double length_m, double speed_mps, const CastingSituation& at,
                        int limit) {
  const int dir = sign(slot.direction);
  const double p = dir * s_m;
  auto clear = [&](double centre_p, double other_length_m, double follower_speed_mps) {
    const double bumper = std::abs(centre_p - p) - 0.5 * (other_length_m + length_m);
    return bumper >= kPlacementStandstill_m + kPlacementTimeGap_s * follower_speed_mps;
  };
  Blockers b;
  for (std::size_t i = 0; i < at.world.size() && b.count < limit; ++i) {
    const ObservedVehicle& v = at.world[i];
    if (!occupies(v, slot.direction, slot.lane)) continue;
    const double q = dir * v.s_m;
    if (clear(q, v.length_m, q < p ? v.speed_mps : speed_mps)) continue;
    if (b.count++ == 0) b.first = static_cast<int>(i);
  }
  const EgoObservation& e = at.ego;
  if (b.count < limit && occupies(e, slot.direction, slot.lane)) {
    const double q = dir * e.s_m;
    if (!clear(q, e.length_m, q < p ? e.speed_mps : speed_mps)) ++b.count;
  }
  return b;
}

// The driver's sight for the director: up to hidden_margin_m beyond the inner region either way.
struct Sight {
  double front_m = 0.0;
  double rear_m = 0.0;
  bool hides(double s_m) const { return s_m > front_m || s_m < rear_m; }
};
Sight sight_of(const WindowBounds& window, const DirectorConfig& cfg) {
  return {window.inner_front_m + cfg.hidden_margin_m, window.inner_rear_m - cfg.hidden_margin_m};
}

// A place out of sight that hidden_placement tries: where, the speed that takes a vehicle from
// there to the slot in time, and the outer region.
struct PlaceTry {
  double s_m = 0.0;
  double needed_mps = 0.0;
  Region region = Region::kOutside;
  bool passes_ego = false;
};

// The places out of sight a vehicle for `slot` could be created at, nearest the ideal one first in
// each outer region (the ideal one: where the slot is now, at its speed), each from where it
// reaches the slot at a speed inside the transport band, and on one lane per direction without
// getting past the ego or anyone else (their neighbours not checked). `take(place)` returns true
// to end that region's search.
template <class Take>
void search_places(const Slot& slot, const CastingSituation& at, const WindowBounds& window,
                   const DirectorConfig& cfg, Take take) {
  const double t = at.time_to_start_s;
  if (t <= 0.0) return;
  const double ideal = slot.s_m - sign(slot.direction) * slot.speed_mps * t;
  const Sight sight = sight_of(window, cfg);
  const struct { double lo, hi; Region region; } zones[] = {
      {sight.front_m, window.front_edge_m - kEdgeMargin_m, Region::kOuterFront},
      {window.rear_edge_m + kEdgeMargin_m, sight.rear_m, Region::kOuterRear},
  };
  const SpeedBand band = transport_band(slot, cfg);
  const bool one_lane = at.lanes.of(slot.direction) <= 1;
  for (const auto& z : zones) {
    if (z.hi <= z.lo) continue;
    const double start = std::clamp(ideal, z.lo, z.hi);
    const bool beyond = z.region == Region::kOuterFront ? ideal > z.hi : ideal < z.lo;
    for (int k = 0; k < kPlacementTries; ++k) {
      const double offset = kPlacementStep_m * ((k + 1) / 2) * (k % 2 == 0 ? 1.0 : -1.0);
      const double s = start + offset;
      if (s < z.lo || s > z.hi) continue;
      const double needed = needed_speed_mps(slot, s, t);
      if (!band.contains(needed)) continue;
      if (beyond && std::abs(needed - slot.speed_mps) > kEarlyCreationSpeedShare * cfg.max_speed_offset_mps) continue;
      const Between b = between(slot, kNoVehicle, s, t, at.world, at.ego, at.ego_s_at_handover_m);
      if (one_lane && (b.ego || b.to_pass > 0 || stuck_between(slot, s, kNoVehicle, at))) continue;
      if (take(PlaceTry{s, needed, z.region, passes_ego_into_its_lane(slot, b, at)})) break;
    }
  }
}
}  // namespace

bool stuck_between(const Slot& slot, double s_m, VehicleId self, const CastingSituation& at) {
  if (at.lanes.of(slot.direction) > 1 || at.ego.direction != slot.direction) return false;
  const int dir = sign(slot.direction);
  const double ego_then_p = dir * at.ego_s_at_handover_m;
  const double slot_p = dir * slot.s_m;
  if (slot_p <= ego_then_p) return false;
  const bool zone_between = std::any_of(at.zones.begin(), at.zones.end(), [&](const ZoneAtStart& z) {
    if (z.direction != slot.direction || z.lane != slot.lane) return false;
    const double a = dir * z.from_s_m;
    const double b = dir * z.to_s_m;
    return std::max(a, b) > ego_then_p && std::min(a, b) < slot_p;
  });
  if (!zone_between) return false;
  const double ego_p = dir * at.ego.s_m;
  const double p = dir * s_m;
  return std::any_of(at.world.begin(), at.world.end(), [&](const ObservedVehicle& v) {
    if (v.id == self || !occupies(v, slot.direction, slot.lane)) return false;
    if (at.oncoming_gap && overtakes_of(at.types, v.type_index)) return false;  // may pass it in the gap
    const double q = dir * v.s_m;
    return q > ego_p && q < p;
  });
}

bool passes_ego_to(const Slot& slot, const ObservedVehicle& v, const CastingSituation& at) {
  return passes_ego_into_its_lane(
      slot, between(slot, v.id, v.s_m, at.time_to_start_s, at.world, at.ego, at.ego_s_at_handover_m), at);
}

double casting_cost(const Slot& slot, const PlayRoleConfig& role, const ObservedVehicle& v, const CastingSituation& at,
                    const DirectorConfig& cfg) {
  if (v.direction != slot.direction || !type_fits(role, v) || at.time_to_start_s <= 0.0) return kInf;
  const SpeedPlan plan = plan_speed(v.speed_mps, slot.speed_mps, at.time_to_start_s,
                                    sign(slot.direction) * (slot.s_m - v.s_m), transport_band(slot, cfg),
                                    transport_rate_mps2(cfg, accel_of(at.types, v.type_index)));
  const bool one_lane = at.lanes.of(slot.direction) <= 1;
  const int dir = sign(slot.direction);
  const bool blocker = one_lane && at.ego.direction == slot.direction && occupies(v, slot.direction, slot.lane) &&
                       !overtakes_of(at.types, v.type_index) && dir * (v.s_m - at.ego.s_m) > 0.0 &&
                       dir * (slot.s_m - at.ego_s_at_handover_m) > 0.0;
  if (std::abs(plan.shortfall_m) > (blocker ? kBlockerSlack : kCastingSlack) * role.position_tolerance_m) return kInf;
  const Between b = between(slot, v.id, v.s_m, at.time_to_start_s, at.world, at.ego, at.ego_s_at_handover_m);
  // On one lane actors do not overtake; faster vehicles may still overtake them (the ego is the
  // driver's to decide: its order must not depend on it).
  if (one_lane && (b.ego || b.to_pass > 0 || stuck_between(slot, v.s_m, v.id, at))) return kInf;
  const int lane_changes = std::abs(v.lane - slot.lane) + b.vehicles + (b.ego ? 1 : 0);
  return std::abs(plan.cruise_mps - v.speed_mps) + cfg.lane_change_cost_mps * lane_changes +
         (passes_ego_into_its_lane(slot, b, at) ? creation_cost(cfg) : 0.0);
}

std::vector<int> cast_roles(const std::vector<Slot>& slots, const std::vector<PlayRoleConfig>& role_configs,
                            const std::vector<bool>& available, const CastingSituation& at, const DirectorConfig& cfg) {
  return cast_roles(slots, role_configs, available, std::vector<CastingSituation>(slots.size(), at), cfg);
}

std::vector<int> cast_roles(const std::vector<Slot>& slots, const std::vector<PlayRoleConfig>& role_configs,
                            const std::vector<bool>& available, const std::vector<CastingSituation>& at_role,
                            const DirectorConfig& cfg, const std::vector<double>& creation_costs) {
  const std::size_t roles = slots.size();
  if (roles == 0) return {};
  const std::vector<ObservedVehicle>& world = at_role.front().world;
  // Only vehicles that could play some role take part (keeps the programme small).
  std::vector<std::size_t> pool;
  std::vector<std::vector<double>> cost(roles);
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (!available[i]) continue;
    std::vector<double> c(roles);
    bool any = false;
    for (std::size_t r = 0; r < roles; ++r) {
      c[r] = casting_cost(slots[r], role_configs[r], world[i], at_role[r], cfg);
      any = any || std::isfinite(c[r]);
    }
    if (!any) continue;
    pool.push_back(i);
    for (std::size_t r = 0; r < roles; ++r) cost[r].push_back(c[r]);
  }
  const std::vector<double> unassigned =
      creation_costs.empty() ? std::vector<double>(roles, creation_cost(cfg)) : creation_costs;
  const std::vector<int> chosen = assign_roles(cost, unassigned);
  std::vector<int> out(roles, -1);
  for (std::size_t r = 0; r < roles; ++r) {
    if (chosen[r] >= 0) out[r] = static_cast<int>(pool[static_cast<std::size_t>(chosen[r])]);
  }
  return out;
}

int cheapest_fit(const Slot& slot, const PlayRoleConfig& role, const std::vector<bool>& available,
                 const CastingSituation& at, const std::vector<int>& taken, const DirectorConfig& cfg) {
  int best = -1;
  double best_cost = kInf;
  for (std::size_t i = 0; i < at.world.size(); ++i) {
    const int index = static_cast<int>(i);
    if (!available[i] || std::find(taken.begin(), taken.end(), index) != taken.end()) continue;
    const double cost = casting_cost(slot, role, at.world[i], at, cfg);
    if (cost < best_cost) {
      best_cost = cost;
      best = index;
    }
  }
  return best;
}

std::optional<Placement> hidden_placement(const Slot& slot, double length_m, const CastingSituation& at,
                                          const WindowBounds& window, const DirectorConfig& cfg) {
  std::optional<Placement> best;
  double best_cost = kInf;
  search_places(slot, at, window, cfg, [&](const PlaceTry& place) {
    if (place_blockers(slot, place.s_m, length_m, place.needed_mps, at, 1).count > 0) return false;
    // As for a vehicle of the traffic (casting_cost): getting past the ego into its lane costs a
    // creation more.
    const double cost = std::abs(place.needed_mps - slot.speed_mps) + (place.passes_ego ? creation_cost(cfg) : 0.0);
    if (cost < best_cost) {
      best_cost = cost;
      best = Placement{place.s_m, place.needed_mps, place.region, place.passes_ego};
    }
    return true;  // the nearest free place to the ideal one in this region
  });
  return best;
}

int blocker_to_take_off(const Slot& slot, double length_m, const std::vector<bool>& available,
                        const CastingSituation& at, const WindowBounds& window, const DirectorConfig& cfg) {
  const Sight sight = sight_of(window, cfg);
  int best = -1;
  double best_cost = kInf;
  search_places(slot, at, window, cfg, [&](const PlaceTry& place) {
    if (place.passes_ego) return false;
    // A single blocker, and a vehicle rather than the ego.
    const Blockers blockers = place_blockers(slot, place.s_m, length_m, place.needed_mps, at, 2);
    if (blockers.count != 1 || blockers.first < 0) return false;
    const auto i = static_cast<std::size_t>(blockers.first);
    if (!available[i] || !sight.hides(at.world[i].s_m)) return false;
    const double cost = std::abs(place.needed_mps - slot.speed_mps);
    if (cost < best_cost) {
      best_cost = cost;
      best = blockers.first;
    }
    return true;
  });
  return best;
}

double creation_cost_for(const std::optional<Placement>& place, const DirectorConfig& cfg) {
  return creation_cost(cfg) * (place && place->passes_ego ? 2.0 : 1.0);
}

}  // namespace entourage::director
