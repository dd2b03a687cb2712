// The director's zone clearing, a phase of a play's preparation (play.hpp): vehicles that would
// stand in a clear zone or in an actor's room at the start are asked out, vehicles in an actor's way
// make way, waiting ones are let in, and shortly before the start the vehicles beside a zone keep
// their lane. How each vehicle is moved: clearing.hpp.
#include <algorithm>
#include <cmath>

#include "director/core/clearing.hpp"
#include "director/core/play.hpp"
#include "director/core/transport.hpp"

namespace entourage::director {

namespace {
// In the last this many seconds before the start, vehicles beside a clear zone (within
// kBesideZone_m of it, where they will be then) keep their lane.
constexpr double kHoldLanesBefore_s = 15.0;
constexpr double kBesideZone_m = 30.0;
// The oncoming lane kept busy (fill_oncoming_lane): no stretch this long on either side of the
// driver's sight without an oncoming vehicle (some 4.5 s apart as they meet the ego at 45 m/s; a
// pass behind a truck at 60 km/h needs a gap of some 500 m); the vehicle created this far beyond
// the sight.
constexpr double kFillSpacing_m = 200.0;
constexpr double kFillBeyondSight_m = 10.0;
// A vehicle created and not yet seen in the world is remembered this long at most.
constexpr double kFillerMemory_s = 2.0;
// A vehicle of the ego's direction this far beyond the actor ahead has passed it (it is moving back in).
constexpr double kPassedBeyond_m = 5.0;
}  // namespace

bool PlayRun::holds_lane_request(const ObservedVehicle& v, int lane, double now_s) const {
  const auto sent = sent_.find(v.id);
  const auto asked = lane_requests_.find(v.id);
  if (sent == sent_.end() || sent->second.mode != ControlMode::kTransported || asked == lane_requests_.end()) {
    return false;
  }
  return keeps_lane_request(v, asked->second, lane, now_s);
}

void PlayRun::note_lane_request(const ObservedVehicle& v, const ActorControl& c, double now_s) {
  if (c.lane < 0 || c.lane == v.lane) {
    lane_requests_.erase(v.id);
    return;
  }
  const auto asked = lane_requests_.find(v.id);
  if (asked == lane_requests_.end() || asked->second.lane != c.lane) lane_requests_[v.id] = {c.lane, now_s};
}

void PlayRun::clear_zones(const PlayInput& in, const std::vector<Slot>& slots, const Aim& aim, double time_to_start_s,
                          PlayOutput& out) {
  const std::vector<ZoneAtStart> zones = zones_of(staged_, in.ego.direction, staged_lane(in), aim.ego_s_m, setting_.lanes);
  // What to clear: the play's zones and the room the actors need at their starts.
  std::vector<double> lengths;
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const ObservedVehicle* v = find(in, roles_[r].actor);
    lengths.push_back(v != nullptr ? v->length_m : in.factory.length_m(std::max(play_.roles[r].type_index, 0)));
  }
  std::vector<ZoneAtStart> to_clear = slot_zones(slots, lengths, in.ego.direction);
  to_clear.insert(to_clear.end(), zones.begin(), zones.end());
  std::vector<ActorPlace> actors;
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const ObservedVehicle* v = find(in, roles_[r].actor);
    if (v != nullptr && v->direction == in.ego.direction) {
      actors.push_back({v->target_lane, v->s_m, v->speed_mps, v->length_m, lane_waited_for(*v, slots[r], aim.time_s)});
    }
  }
  const ClearingSituation situation{to_clear, aim.time_s,     in.ego,           aim.ego_s_m,
                                    slots,    setting_.lanes, setting_.director, actors,
                                    setting_.types};
  // Vehicle i, ours from now on, is told to clear out (a cleared one keeps its last command until
  // the handover); a speed is given with the lead actors get (drive_speed_mps).
  auto clear = [&](std::size_t i, const Clearance& c) {
    const ObservedVehicle& v = in.world[i];
    if (is_cleared(v.id) && holds_lane_request(v, c.lane, in.ego.time_s)) return;
    if (!is_cleared(v.id)) {
      cleared_.push_back(v.id);
      in.available[i] = false;
    }
    double drive_mps = c.speed_mps;
    if (drive_mps != kOwnDesiredSpeed_mps) {
      const double type_accel = accel_of(setting_.types, v.type_index);
      drive_mps = drive_speed_mps(drive_mps, v.speed_mps, transport_rate_mps2(setting_.director, type_accel), type_accel);
      drive_mps = std::min(drive_mps, top_speed_of(setting_.types, v.type_index));
    }
    const ActorControl control = transported(drive_mps, c.lane);
    note_lane_request(v, control, in.ego.time_s);
    command(v.id, control, in.step, out);
  };
  auto ours_or_free = [&](std::size_t i) { return is_cleared(in.world[i].id) || in.available[i]; };  // not an actor
  for (std::size_t i = 0; i < in.world.size(); ++i) {
    if (!ours_or_free(i)) continue;
    if (const auto c = clear_out(in.world[i], situation)) clear(i, *c);
  }
  // Vehicles in an actor's way to its slot make way where they can.
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const ObservedVehicle* actor = find(in, roles_[r].actor);
    if (actor == nullptr) continue;
    const auto sent = sent_.find(actor->id);
    const int actor_cmd_lane = sent != sent_.end() ? sent->second.lane : -1;
    for (std::size_t i = 0; i < in.world.size(); ++i) {
      if (!ours_or_free(i)) continue;
      if (const auto c = make_way(in.world[i], slots[r], *actor, roles_[r].command_mps, actor_cmd_lane, situation)) {
        clear(i, *c);
      }
    }
  }
  let_in(in, slots, aim.time_s, out);
  hold_followers(in, out);
  if (time_to_start_s > kHoldLanesBefore_s) return;
  // Shortly before the start, vehicles beside a zone keep their lane (at their own speed), so that
  // none changes into it at the last moment.
  for (std::size_t i = 0; i < in.world.size(); ++i) {
    const ObservedVehicle& v = in.world[i];
    const bool ours = is_cleared(v.id);
    if (ours || !in.available[i] || v.lane != v.target_lane) continue;
    const double s_then = s_after_m(v, aim.time_s);
    const bool beside = std::any_of(zones.begin(), zones.end(), [&](const ZoneAtStart& z) {
      return z.direction == v.direction && std::abs(v.lane - z.lane) == 1 && s_then > z.from_s_m - kBesideZone_m &&
             s_then < z.to_s_m + kBesideZone_m;
    });
    if (!beside) continue;
    cleared_.push_back(v.id);
    in.available[i] = false;
    command(v.id, transported(kOwnDesiredSpeed_mps, v.lane), in.step, out);
  }
}

bool PlayRun::zone_ahead_on_one_lane(const PlayInput& in) const {
  return setting_.lanes.of(in.ego.direction) == 1 &&
         std::any_of(staged_.clear.begin(), staged_.clear.end(),
                     [](const PlayClearZoneConfig& z) { return z.lane_offset == 0 && z.to_m > 0.0; });
}

bool PlayRun::opens_oncoming_gap(const PlayInput& in) const {
  return setting_.director.oncoming_gap_m > 0.0 && zone_ahead_on_one_lane(in);
}

bool PlayRun::ahead_in_ego_lane(const PlayRoleConfig& rc) {
  return rc.direction == Direction::kForward && rc.lane_offset == 0 && rc.ahead_m > 0.0;
}

bool PlayRun::someone_between(const PlayInput& in) const {
  // The roles ahead of the ego in its lane at the start (the truck): an actor not cast yet, or a
  // vehicle of the ego's direction between the ego and its actor now, unless it is already
  // passing (in the oncoming lane, or moving there): it will be out of the way.
  const int dir = sign(in.ego.direction);
  const double ego_p = dir * in.ego.s_m;
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    if (!ahead_in_ego_lane(staged_.roles[r])) continue;
    const ObservedVehicle* a = find(in, roles_[r].actor);
    if (a == nullptr) return true;
    const double a_p = dir * a->s_m;
    for (const ObservedVehicle& v : in.world) {
      const double p = dir * v.s_m;
      if (v.id != a->id && v.direction == in.ego.direction && p > ego_p && p < a_p && !passing(v, setting_.lanes)) {
        return true;
      }
    }
  }
  return false;
}

void PlayRun::open_oncoming_gap(const PlayInput& in, PlayOutput& out) {
  const int dir = sign(in.ego.direction);
  const double from_trigger1_m = dir * (in.ego.s_m - play_.trigger1_s_m);
  if (!opens_oncoming_gap(in) || from_trigger1_m < 0.0) return;
  if (from_trigger1_m > setting_.director.oncoming_gap_m || !someone_between(in)) {
    fill_oncoming_lane(in, out);
    return;
  }
  const double out_of_sight_m = sight_edge_m();
  for (std::size_t i = 0; i < in.world.size(); ++i) {
    const ObservedVehicle& v = in.world[i];
    if (!in.available[i] || v.direction == in.ego.direction || dir * (v.s_m - in.ego.s_m) <= out_of_sight_m) continue;
    in.available[i] = false;
    command(v.id, withdrawn(), in.step, out);
  }
}

double PlayRun::actors_ahead_in_view_m(const PlayInput& in) const {
  const int dir = sign(in.ego.direction);
  double farthest_m = -1.0;
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    if (!ahead_in_ego_lane(staged_.roles[r])) continue;
    const ObservedVehicle* a = find(in, roles_[r].actor);
    if (a == nullptr) return -1.0;
    const double ahead = dir * (a->s_m - in.ego.s_m);
    if (ahead <= 0.0 || ahead >= setting_.window.inner_ahead_m) return -1.0;
    farthest_m = std::max(farthest_m, ahead);
  }
  return farthest_m;
}

bool PlayRun::someone_passing_behind(const PlayInput& in, double actor_ahead_m) const {
  const int dir = sign(in.ego.direction);
  return std::any_of(in.world.begin(), in.world.end(), [&](const ObservedVehicle& v) {
    const double ahead = dir * (v.s_m - in.ego.s_m);
    return v.direction == in.ego.direction && passing(v, setting_.lanes) && ahead > 0.0 &&
           ahead < actor_ahead_m + kPassedBeyond_m;
  });
}

bool PlayRun::oncoming_near_sight(const PlayInput& in, double sight_m) const {
  const int dir = sign(in.ego.direction);
  auto near = [&](double s_m) { return std::abs(dir * (s_m - in.ego.s_m) - sight_m) < kFillSpacing_m; };
  const bool seen = std::any_of(in.world.begin(), in.world.end(), [&](const ObservedVehicle& v) {
    return v.direction != in.ego.direction && near(v.s_m);
  });
  // Vehicles created before and not published yet count where they would be now.
  return seen || std::any_of(fillers_.begin(), fillers_.end(), [&](const Filler& f) {
           return near(f.s_m - dir * f.speed_mps * (in.ego.time_s - f.time_s));
         });
}

void PlayRun::fill_oncoming_lane(const PlayInput& in, PlayOutput& out) {
  if (passing(in.ego, setting_.lanes)) return;
  const double actor_ahead_m = actors_ahead_in_view_m(in);
  if (actor_ahead_m <= 0.0 || someone_between(in) || someone_passing_behind(in, actor_ahead_m)) return;
  fillers_.erase(std::remove_if(fillers_.begin(), fillers_.end(),
                                [&](const Filler& f) {
                                  return find(in, f.id) != nullptr || in.ego.time_s - f.time_s > kFillerMemory_s;
                                }),
                 fillers_.end());
  const double sight_m = sight_edge_m();
  if (oncoming_near_sight(in, sight_m)) return;
  // A car of the play's first oncoming role, at the speed of the oncoming traffic ahead of the ego
  // (or that role's start speed).
  const int dir = sign(in.ego.direction);
  const auto role = std::find_if(staged_.roles.begin(), staged_.roles.end(),
                                 [](const PlayRoleConfig& rc) { return rc.direction != Direction::kForward; });
  double speed_sum = 0.0;
  int speed_count = 0;
  for (const ObservedVehicle& v : in.world) {
    if (v.direction == in.ego.direction || dir * (v.s_m - in.ego.s_m) <= 0.0) continue;
    speed_sum += v.speed_mps;
    ++speed_count;
  }
  if (speed_count == 0 && role == staged_.roles.end()) return;
  const double speed = speed_count > 0 ? speed_sum / speed_count : start_speed_mps(*role, in.ego.speed_mps);
  const int type = role != staged_.roles.end() ? std::max(role->type_index, 0) : 0;
  const double s_m = in.ego.s_m + dir * (sight_m + kFillBeyondSight_m);
  Vehicle v = in.factory.make(type, opposite(in.ego.direction), 0, s_m, speed);
  fillers_.push_back({v.id, s_m, speed, in.ego.time_s});
  out.created.push_back({std::move(v), Region::kOuterFront});
}

void PlayRun::hold_followers(const PlayInput& in, PlayOutput& out) {
  const int lane = staged_lane(in);
  if (!zone_ahead_on_one_lane(in) || in.ego.lane != lane || in.ego.target_lane != lane) return;
  const int dir = sign(in.ego.direction);
  for (std::size_t i = 0; i < in.world.size(); ++i) {
    const ObservedVehicle& v = in.world[i];
    const double behind_m = dir * (in.ego.s_m - v.s_m);
    if (!in.available[i] || is_cleared(v.id) || v.direction != in.ego.direction || v.lane != lane ||
        v.target_lane != lane || behind_m <= 0.0 || behind_m > setting_.window.inner_behind_m) {
      continue;
    }
    cleared_.push_back(v.id);
    in.available[i] = false;
    command(v.id, transported(kOwnDesiredSpeed_mps, lane), in.step, out);
  }
}

bool PlayRun::holds_an_actor_up(const PlayInput& in, const std::vector<Slot>& slots, const ObservedVehicle& follower,
                                int lane, double hold_mps) const {
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const ObservedVehicle* actor = find(in, roles_[r].actor);
    if (actor == nullptr || slots[r].lane != lane) continue;
    if (held_back_holds_up(follower, hold_mps, slots[r], *actor, roles_[r].command_mps)) return true;
  }
  return false;
}

int PlayRun::waiting_for_lane(const PlayInput& in, VehicleId id) const {
  const auto cmd = sent_.find(id);
  const ObservedVehicle* v = find(in, id);
  if (cmd == sent_.end() || v == nullptr || cmd->second.mode != ControlMode::kTransported) return -1;
  const int lane = cmd->second.lane;
  const bool waits = lane >= 0 && v->lane == v->target_lane && v->lane != lane && v->indicator != 0;
  return waits ? lane : -1;
}

void PlayRun::stop_holding_back(const PlayInput& in, VehicleId id, PlayOutput& out) {
  const ObservedVehicle* v = find(in, id);
  if (v == nullptr || role_of(id) < roles_.size()) return;
  lane_requests_.erase(id);
  command(id, transported(kOwnDesiredSpeed_mps, v->lane), in.step, out);
}

void PlayRun::end_hold_backs_no_longer_needed(const PlayInput& in, PlayOutput& out) {
  for (auto it = letting_in_.begin(); it != letting_in_.end();) {
    if (waiting_for_lane(in, it->first) >= 0) {
      ++it;
      continue;
    }
    stop_holding_back(in, it->second, out);
    it = letting_in_.erase(it);
  }
}

std::vector<VehicleId> PlayRun::waiting_to_be_let_in(const PlayInput& in, const std::vector<Slot>& slots) const {
  // The cleared vehicles, and an actor ahead of the ego in the ego's lane that waits to leave it
  // for its start's lane: it cannot fall back there to find a gap (leaving_ego_lane_floor_mps), and
  // waited in vain (cut-in, seed 37, stop 55: a column of cleared cars 4 m/s faster than the cutter
  // passed it for 60 s in the lane it signalled for). Not an actor on its way into the ego's lane:
  // the one letting it in stays between it and the ego, in the play's clear zone there (lead
  // vehicle, stop 55, every waiting actor let in: 371 of seeds 1-400 against 385, 19 runs lost,
  // most of them with a vehicle in the zone, 5 gained); nor one that leaves it to pass a slower
  // vehicle (lead vehicle, every actor leaving the ego's lane ahead of it let in: 382 against 385,
  // 4 runs lost with the lead in the wrong lane, 1 gained).
  std::vector<VehicleId> waiting = cleared_;
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const ObservedVehicle* a = find(in, roles_[r].actor);
    if (a == nullptr || slots[r].direction != in.ego.direction) continue;
    const int start_lane = slots[r].lane;
    if (waiting_for_lane(in, a->id) == start_lane && leaves_ego_lane_ahead(in, *a, start_lane)) waiting.push_back(a->id);
  }
  return waiting;
}

void PlayRun::let_in(const PlayInput& in, const std::vector<Slot>& slots, double time_left_s, PlayOutput& out) {
  end_hold_backs_no_longer_needed(in, out);
  for (VehicleId id : waiting_to_be_let_in(in, slots)) {
    const int lane = waiting_for_lane(in, id);
    // One holding back for another is not let in itself meanwhile.
    if (lane >= 0 && !holding_back(id)) let_in_one(in, slots, time_left_s, *find(in, id), lane, out);
  }
}

void PlayRun::let_in_one(const PlayInput& in, const std::vector<Slot>& slots, double time_left_s,
                         const ObservedVehicle& v, int lane, PlayOutput& out) {
  const VehicleId id = v.id;
  const ObservedVehicle* f = follower_to_let_in(v, lane, in.world, in.ego);
  const auto before = letting_in_.find(id);
  if (f == nullptr) {
    // Beside a standing one, one that held back would stand there with it for good: it drives
    // on as it likes (moving, one that fell back out of reach holds on until it has moved over).
    if (before != letting_in_.end() && nearly_stands(v)) {
      stop_holding_back(in, before->second, out);
      letting_in_.erase(before);
    }
    return;
  }
  const auto i = static_cast<std::size_t>(f - in.world.data());
  const bool for_it_already = before != letting_in_.end() && before->second == f->id;
  // One vehicle holds back for each, the one just behind it: one that did so before and no longer
  // is (it fell back, or another came between) drives on as it likes, whether or not the new one
  // may hold back.
  if (before != letting_in_.end() && !for_it_already) {
    stop_holding_back(in, before->second, out);
    letting_in_.erase(before);
  }
  // An actor in place beside its start that waits to move into v's lane, its start's, lets v into
  // its own first: the two swap lanes (lane_waited_for, clearing.hpp). It holds back in
  // move_actors.
  const std::size_t r = role_of(f->id);
  const bool swapping_actor = r < roles_.size() && lane_waited_for(*f, slots[r], time_left_s) == v.lane &&
                              waiting_for_lane(in, f->id) == v.lane;
  if ((holding_back(f->id) && !for_it_already) || !(is_cleared(f->id) || in.available[i] || swapping_actor)) {
    return;  // it lets in another, or it is an actor or another play's
  }
  if (swapping_actor) {
    letting_in_[id] = f->id;
    return;
  }
  // Never asked above its type's top speed: behind a faster waiting vehicle, a truck was asked to
  // 33 m/s where trucks wish 26.4 at most.
  const double hold_mps = std::min(v.speed_mps - kLetIn_mps, top_speed_of(setting_.types, f->type_index));
  // Never by holding an actor up (held_back_holds_up): the waiting one waits for a gap, or for
  // another to let it in.
  if (holds_an_actor_up(in, slots, *f, lane, hold_mps)) {
    if (for_it_already) {
      stop_holding_back(in, f->id, out);
      letting_in_.erase(before);
    }
    return;
  }
  // It waits to move over itself, unless into the lane of the one it would let in: two cleared
  // vehicles alongside each other, each asked into the other's lane, each waited for the other
  // to let it in (a cut-in's cutter held up behind them for 30 s, seed 154); the one ahead moves
  // first.
  const auto f_asked = lane_requests_.find(f->id);
  const bool swap = f_asked != lane_requests_.end() && f_asked->second.lane == v.lane;
  if (is_cleared(f->id) && holds_lane_request(*f, f->lane, in.ego.time_s) && !swap) return;
  if (!is_cleared(f->id)) {
    cleared_.push_back(f->id);
    in.available[i] = false;
  }
  letting_in_[id] = f->id;
  lane_requests_.erase(f->id);
  command(f->id, transported(std::max(0.0, hold_mps), f->lane), in.step, out);
}

}  // namespace entourage::director
