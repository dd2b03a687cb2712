#include "director/core/clearing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "director/core/transport.hpp"

namespace entourage::director {

namespace {
// Extra room around a zone a cleared vehicle must keep.
constexpr double kZoneMargin_m = 5.0;
// A vehicle is not sent into a lane where an actor starts faster than its type's top speed less
// this (slower_than_an_actor_of), and a way out of a zone by its speed counts as one before a swap
// of lanes with an actor only this far below that top (clear_out).
constexpr double kTopSpeedMargin_mps = 1.0;
// A cleared vehicle is planned to be out of the zone this long before the start (half the time
// left, once less than twice this is left): a plan spread over all the time left runs late, as
// the driver lags its desired speed and the ego's own speed changes move the zone.
constexpr double kClearEarly_s = 5.0;

double clearing_time_s(double time_left_s) {
  return time_left_s > 2.0 * kClearEarly_s ? time_left_s - kClearEarly_s : 0.5 * time_left_s;
}

// An actor of `lane` alongside `v` now: `v` overlaps the room the actor keeps around it where it
// is (actor_room, with the actor's own length). Moving into that lane would cut in on the actor,
// which waits to move into v's lane in turn. (A car asked out of the lead's room waited 40 s
// beside the lead, which waited to move in beside it: lead vehicle, seed 10. Until stop 54 the
// room was built with v's length, 6 m longer each way for a truck: a truck the ego followed in a
// cut-in's zone, its rear 33-38 m ahead of the cutter's centre, counted as alongside the cutter
// and never moved over; seeds 294 and 313.) With `swapping`, an actor in place beside its start
// that waits to move into v's lane, its start's, does not count: the two swap lanes, the actor
// letting v in first (lane_waited_for).
bool alongside_an_actor(const ObservedVehicle& v, int lane, const std::vector<ActorPlace>& actors,
                        bool swapping = false) {
  return std::any_of(actors.begin(), actors.end(), [&](const ActorPlace& a) {
    return a.lane == lane && !(swapping && a.waits_for_lane == v.lane) &&
           in_zone(actor_room(v.direction, a.lane, a.s_m, a.length_m, a.speed_mps), lane, v.s_m, v.length_m);
  });
}

// The speed at which a cleared vehicle covers `distance_m` (to a road position it must reach by the
// start, `time_left_s` from now): in `t_plan_s` (clearing_time_s early) where that is within
// [low, high], else just by the start. Early asks for more than any driver does late in the
// preparation, and for a target behind a zone, which moves on with the ego, it asks for more than
// the ego's speed: a car in the zone beside the ego, behind the cutter, was sent to the top of the
// band instead of falling back 10 m, and stood in the zone (cut-in, seed 70).
double clearing_speed_mps(double distance_m, double t_plan_s, double time_left_s, double low, double high) {
  const double early = distance_m / t_plan_s;
  if (early >= low && early <= high) return early;
  return distance_m / std::max(time_left_s, t_plan_s);
}

// A role of the ego's direction starts in `lane`.
bool a_role_lane(int lane, const ClearingSituation& at) {
  return std::any_of(at.slots.begin(), at.slots.end(),
                     [&](const Slot& s) { return s.direction == at.ego.direction && s.lane == lane; });
}

// An actor starts in `lane` faster than any driver of v's type wishes to drive: v, sent there
// ahead of it, would be caught by it and hold it back. (A truck sent from the ego's lane into the
// cutter's, ahead of the cutter's room, held the cutter back at its top speed in 14 of the cut-in's
// 51 failures on seeds 1-200, stop 45: sent there a minute before the start, it could not stay
// ahead once the ego, and the cutter's start speed with it, had sped up.)
//
// The exception, late in the preparation (kLateMoveWindow_s before the start): the ego's leader
// that the ego follows at its speed (within kFollowedSpeedBand_mps) cannot get out of a zone ahead
// of the ego by its speed, and it may move in ahead of an actor that is on its way to its place
// already (its start within kActorInPlace_m at its present speed), if at its present speed it is
// ahead of that lane's zones, the actor's room included, at the start: the actor does not catch up
// with it before the start, and leaves that lane once the play begins. (In 10 of the cut-in's 41
// failures on seeds 1-200, stop 46, a truck at 24.4-26.4 m/s 54-65 m ahead of an ego following it
// stood in the zone, which ends 60 m ahead, the cutter in place beside the ego. Where the ego
// closes on the leader, the leader leaves the zone behind by itself; moved over then, it slowed the
// vehicles in the actor's lane and the actor with them.)
bool moves_in_late(const ObservedVehicle& v, const Slot& s, const ClearingSituation& at, double zones_front_p) {
  const double t = std::max(at.time_left_s, 0.0);
  if (t > kLateMoveWindow_s || std::abs(at.ego.speed_mps - v.speed_mps) > kFollowedSpeedBand_mps) return false;
  const double dir = sign(v.direction);
  const double rear_then_p = dir * s_after_m(v, t) - 0.5 * v.length_m;
  if (rear_then_p < zones_front_p) return false;
  return std::any_of(at.actors.begin(), at.actors.end(), [&](const ActorPlace& a) {
    return a.lane == s.lane && std::abs(dir * (a.s_m - s.s_m) + a.speed_mps * t) <= kActorInPlace_m;
  });
}

// "Faster" with a margin (kTopSpeedMargin_mps): an actor's start speed relative to the ego's rises
// with the ego's, and the ego often speeds up after v has moved over (since stop 50: with the
// start speed compared with the top speed alone, a truck sent into the cutter's lane while the
// cutter was to start 0-0.9 m/s below the truck's top was caught by the cutter once the ego sped
// up, as in cut-in seeds 13, 31, 137 and 188).
bool slower_than_an_actor_of(const ObservedVehicle& v, int lane, const ClearingSituation& at, double zones_front_p) {
  const double top_mps = top_speed_of(at.types, v.type_index);
  return std::any_of(at.slots.begin(), at.slots.end(), [&](const Slot& s) {
    return s.direction == v.direction && s.lane == lane && s.speed_mps > top_mps - kTopSpeedMargin_mps &&
           !moves_in_late(v, s, at, zones_front_p);
  });
}

// A neighbouring lane of `v`'s in which it can be ahead of every zone of that lane by the start
// (clearing_time_s early where that is within the band, else just by the start: late in the
// preparation early asks for more than any driver does) at a speed within [low, high], out of its
// actors' way (ActorPlace) and of no actor that starts there faster than v's type
// drives; the one that needs the smaller change of speed. Its own desired speed where its present
// one is enough already.
std::optional<Clearance> ahead_in_next_lane(const ObservedVehicle& v, const ClearingSituation& at, double t_plan,
                                            double low, double high) {
  const int dir = sign(v.direction);
  const double p = dir * v.s_m;
  std::optional<Clearance> best;
  double best_change = 0.0;
  for (int lane : {v.lane - 1, v.lane + 1}) {
    if (lane < 0 || lane >= at.lanes.of(v.direction) || alongside_an_actor(v, lane, at.actors)) continue;
    double front_p = -std::numeric_limits<double>::infinity();
    for (const ZoneAtStart& z : at.zones) {
      if (z.direction == v.direction && z.lane == lane) front_p = std::max(front_p, dir > 0 ? z.to_s_m : -z.from_s_m);
    }
    if (slower_than_an_actor_of(v, lane, at, front_p)) continue;
    // Moved in late (moves_in_late), it is ahead of that lane's zones at its present speed already:
    // no margin on top. (With kZoneMargin_m on top, trucks the ego followed at about their type's
    // top speed, a few metres ahead of the cutter's room at the start, were asked for more than
    // that top, stayed in the zone ahead of the ego and failed the cut-in: seeds 6, 27, 221 and
    // 259, stop 54.)
    const bool late = std::any_of(at.slots.begin(), at.slots.end(), [&](const Slot& s) {
      return s.direction == v.direction && s.lane == lane && moves_in_late(v, s, at, front_p);
    });
    const double target_p = front_p + 0.5 * v.length_m + (late ? 0.0 : kZoneMargin_m);
    const double speed = clearing_speed_mps(target_p - p, t_plan, at.time_left_s, low, high);
    if (speed > high) continue;
    const double drive_mps = std::max(speed, v.speed_mps);
    // In an actor's way: ahead of it now, and within its reach before the start.
    const bool in_an_actors_way = std::any_of(at.actors.begin(), at.actors.end(), [&](const ActorPlace& a) {
      if (a.lane != lane) return false;
      const double gap_m = p - dir * a.s_m;
      return gap_m <= 0.0 || gap_m < (a.speed_mps - drive_mps) * at.time_left_s;
    });
    if (in_an_actors_way) continue;
    const double change = std::max(0.0, speed - v.speed_mps);
    if (best && change >= best_change) continue;
    best_change = change;
    // Moved in late, it keeps at least its present speed, at which it is ahead of the zones: left to
    // its own desired speed once over, a truck commanded at its type's top slowed by 1.5 m/s in
    // front of the cutter and held it back (cut-in seeds 51 and 215, stop 54).
    if (late) {
      best = Clearance{std::max(speed, v.speed_mps), lane};
    } else {
      best = Clearance{speed <= v.speed_mps ? kOwnDesiredSpeed_mps : std::max(speed, low), lane};
    }
  }
  return best;
}
}  // namespace

std::optional<Clearance> clear_out(const ObservedVehicle& v, const ClearingSituation& at) {
  const double t = std::max(at.time_left_s, 0.0);
  const int dir = sign(v.direction);
  const double s_then = s_after_m(v, t);
  const ZoneAtStart* hit = zone_hit(at.zones, v, s_then);
  if (hit == nullptr) return std::nullopt;
  // A neighbouring lane that no zone and no role needs (with `swapping`, also one where an actor
  // alongside waits in place to move into v's lane: alongside_an_actor).
  auto free_lane = [&](int lane, bool swapping) {
    if (lane < 0 || lane >= at.lanes.of(v.direction) || alongside_an_actor(v, lane, at.actors, swapping)) return false;
    for (const ZoneAtStart& z : at.zones) {
      if (z.lane == lane && z.direction == v.direction) return false;
    }
    return !a_role_lane(lane, at);
  };
  auto onto_free_lane = [&](bool swapping) -> std::optional<Clearance> {
    for (int lane : {v.lane - 1, v.lane + 1}) {  // the right one first
      if (free_lane(lane, swapping)) return Clearance{kOwnDesiredSpeed_mps, lane};
    }
    return std::nullopt;
  };
  if (const auto moved = onto_free_lane(false)) return moved;
  // Swapping lanes with an actor in place beside it comes after getting out by its speed in its
  // own lane: it holds the actor back while it lets v in (lead vehicle, seed 110, stop 67: a car the
  // lead let in ahead of it, where it could have been ahead of the lead's room by its speed, left
  // the lead behind its start).
  // On one lane a vehicle can only get out of a zone ahead of the ego by passing what is ahead of
  // it, or fall behind the ego by being passed: it is left to its own driving (it overtakes a
  // slow actor by itself when the oncoming traffic lets it).
  if (t <= 0.0 || at.lanes.of(v.direction) <= 1) return onto_free_lane(true);
  const double p = dir * v.s_m;
  const DirectorConfig& cfg = at.cfg;
  // The band around its speed, never above the highest speed its type's drivers wish (trucks were
  // asked up to 127 km/h to get ahead of a zone where trucks wish 95 at most: cut-in, stop 44).
  const double high = std::min(v.speed_mps + cfg.max_speed_offset_mps,
                               std::max(v.speed_mps, top_speed_of(at.types, v.type_index)));
  const double low = std::min(high, std::max(0.0, std::max(cfg.min_speed_mps, v.speed_mps - cfg.max_speed_offset_mps)));
  // Out early (clearing_time_s).
  const double t_plan = clearing_time_s(t);
  const EgoObservation& ego = at.ego;
  const bool with_ego = occupies(ego, v.direction, v.lane);
  const bool ahead_of_ego = dir * v.s_m > dir * ego.s_m;
  if (with_ego && ahead_of_ego) {
    if (const auto moved = ahead_in_next_lane(v, at, t_plan, low, high)) return moved;
  }
  // Ahead of the zone or behind it, whichever needs the smaller change of speed; the zone joined
  // with those of its lane too close to it to stand between.
  const ZoneAtStart zone = joined_zone(*hit, at.zones, v.length_m + 2.0 * kZoneMargin_m);
  const double front_p = dir > 0 ? zone.to_s_m : -zone.from_s_m;
  const double rear_p = dir > 0 ? zone.from_s_m : -zone.to_s_m;
  const double ahead_p = front_p + 0.5 * v.length_m + kZoneMargin_m;
  const double behind_p = rear_p - 0.5 * v.length_m - kZoneMargin_m;
  // In the ego's lane it cannot get past the ego, nor the ego past it: a vehicle ahead of the ego
  // stays ahead (asked to fall back behind a zone in front of the ego, it would hold the ego up,
  // and the zone, which moves with the ego, with it).
  const double ego_then_p = dir * at.ego_s_then_m;
  const double room_p = 0.5 * (v.length_m + ego.length_m) + kZoneMargin_m;
  auto keeps_order = [&](double target_p) {
    if (!with_ego) return true;
    return ahead_of_ego ? target_p > ego_then_p + room_p : target_p < ego_then_p - room_p;
  };
  // Nor can it get past an actor of its lane, nor that actor past it: a vehicle ahead of one is
  // only sent ahead of the zone, one behind only behind it. (Sent behind the room a cutter needs,
  // the car just ahead of the cutter in its lane slowed to fall back and took the cutter back with
  // it, 27 m behind its start: cut-in, seed 61.)
  const auto actor_ahead_or_behind = [&](bool ahead) {
    return std::any_of(at.actors.begin(), at.actors.end(),
                       [&](const ActorPlace& a) { return a.lane == v.lane && (dir * a.s_m > p) == ahead; });
  };
  const bool behind_an_actor = actor_ahead_or_behind(true);
  const bool ahead_of_an_actor = actor_ahead_or_behind(false);
  // When neither way is within the band, the edge of the band towards the first way that keeps
  // the order: as far out as it gets (it was left with its last command before, which had asked
  // for too little).
  // (The target is the edge's road position at the start, reached kClearEarly_s early where that
  // is within the band, else by the start (clearing_speed_mps): a vehicle planned to be behind a
  // zone then drives on past that position before the start, out of a short zone ahead of it. A
  // plan that really falls back slowed the vehicle's lane behind it down and made the plays fail
  // more often: services/director/README.md, Pacing.)
  std::optional<Clearance> best;
  std::optional<Clearance> closest;
  // Each way with whether it would pass an actor of its lane.
  const std::pair<double, bool> ways[] = {{ahead_p, behind_an_actor}, {behind_p, ahead_of_an_actor}};
  for (const auto& [target_p, passes_an_actor] : ways) {
    if (passes_an_actor || !keeps_order(target_p)) continue;
    const double speed = clearing_speed_mps(target_p - p, t_plan, t, low, high);
    if (speed < low || speed > high) {
      if (!closest) closest = Clearance{std::clamp(speed, low, high), v.lane};
      continue;
    }
    if (!best || std::abs(speed - v.speed_mps) < std::abs(best->speed_mps - v.speed_mps)) best = Clearance{speed, v.lane};
  }
  // By its speed only with a margin below its type's top (kTopSpeedMargin_mps): a truck asked for
  // its top to get ahead of the lead's room never got there, the ego behind it at the same speed
  // (lead vehicle, seed 37, stop 67).
  if (best && best->speed_mps <= top_speed_of(at.types, v.type_index) - kTopSpeedMargin_mps) return best;
  // Swapped, it keeps the speed its own lane's way asked for (at its own desired speed, a truck in
  // the stopper's room that its top speed would have taken ahead of the room, the stopper slowing
  // to its start, waited in it and the play failed: stopped vehicle, seed 107, stop 67).
  const std::optional<Clearance> by_speed = best ? best : closest;
  if (const auto swapped = onto_free_lane(true)) {
    return Clearance{by_speed ? by_speed->speed_mps : kOwnDesiredSpeed_mps, swapped->lane};
  }
  return by_speed;
}

std::optional<Clearance> make_way(const ObservedVehicle& v, const Slot& slot, const ObservedVehicle& actor,
                                  double actor_cmd_mps, int actor_cmd_lane, const ClearingSituation& at) {
  if (v.lane != v.target_lane) return std::nullopt;  // already changing lanes
  if (!holds_up(v, slot.direction, slot.lane, sign(slot.direction) * slot.s_m, actor, actor_cmd_mps)) return std::nullopt;
  const double s_then = s_after_m(v, std::max(at.time_left_s, 0.0));
  auto clear_lane = [&](int lane) {
    if (lane < 0 || lane >= at.lanes.of(v.direction)) return false;
    if (a_role_lane(lane, at)) return false;
    if (occupies(actor, v.direction, lane) || lane == actor_cmd_lane) return false;
    return std::none_of(at.zones.begin(), at.zones.end(), [&](const ZoneAtStart& z) {
      return z.direction == v.direction && in_zone(z, lane, s_then, v.length_m + 2.0 * kZoneMargin_m);
    });
  };
  for (int lane : {v.lane - 1, v.lane + 1}) {  // the right one first
    if (clear_lane(lane)) return Clearance{actor_cmd_mps, lane};
  }
  return std::nullopt;
}

int lane_waited_for(const ObservedVehicle& actor, const Slot& start, double time_left_s) {
  if (actor.direction != start.direction || actor.lane == start.lane || actor.target_lane != actor.lane) return -1;
  const double off_m = sign(actor.direction) * (s_after_m(actor, std::max(time_left_s, 0.0)) - start.s_m);
  return std::abs(off_m) <= kActorInPlace_m ? start.lane : -1;
}

bool keeps_lane_request(const ObservedVehicle& v, const LaneRequest& asked, int lane, double now_s) {
  if (asked.lane < 0 || asked.lane == lane || v.lane == asked.lane) return false;
  if (v.target_lane == asked.lane) return true;  // moving over: never reversed midway
  return now_s - asked.since_s < kHoldLaneRequest_s;
}

const ObservedVehicle* follower_to_let_in(const ObservedVehicle& waiting, int lane,
                                          const std::vector<ObservedVehicle>& world, const EgoObservation& ego) {
  const double front_p = waiting.progress_m() + 0.5 * waiting.length_m;
  const double rear_p = waiting.progress_m() - 0.5 * waiting.length_m;
  // Beside a waiting vehicle that nearly stands, one holding back stands too and never falls
  // behind it: that one drives on, and the one behind it lets it in.
  const bool standing = nearly_stands(waiting);
  const ObservedVehicle* nearest = nullptr;
  for (const ObservedVehicle& w : world) {
    if (w.id == waiting.id || w.direction != waiting.direction || !occupies(w, w.direction, lane)) continue;
    const double w_front_p = w.progress_m() + 0.5 * w.length_m;
    if (w_front_p > front_p || (standing && w_front_p > rear_p)) continue;
    if (nearest == nullptr || w.progress_m() > nearest->progress_m()) nearest = &w;
  }
  if (nearest == nullptr) return nullptr;
  if (ego.direction == waiting.direction && occupies(ego, ego.direction, lane)) {
    const double ego_p = ego.progress_m();
    if (ego_p + 0.5 * ego.length_m <= front_p && ego_p > nearest->progress_m()) return nullptr;
  }
  const double gap_m = rear_p - (nearest->progress_m() + 0.5 * nearest->length_m);
  return gap_m < std::max(kLetInReach_s * nearest->speed_mps, kLetInQueueReach_m) ? nearest : nullptr;
}

bool held_back_holds_up(const ObservedVehicle& follower, double hold_mps, const Slot& start,
                        const ObservedVehicle& actor, double actor_cmd_mps) {
  const int dir = sign(start.direction);
  if (dir * start.s_m <= dir * actor.s_m || !occupies(actor, start.direction, start.lane)) return false;
  ObservedVehicle held = follower;
  held.speed_mps = hold_mps;
  return holds_up(held, start.direction, start.lane, std::numeric_limits<double>::infinity(), actor, actor_cmd_mps);
}

}  // namespace entourage::director
