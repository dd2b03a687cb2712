#include "director/core/play.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace entourage::director {

namespace {
// A new start-time estimate is reported when it moves by more than this.
constexpr double kEstimateReportThreshold_s = 1.0;
// Casting is retried this often while a role has no actor.
constexpr double kCastInterval_s = 1.0;
// Transport progress (the errors) is reported this often.
constexpr double kProgressReportInterval_s = 1.0;
// A created vehicle appears in the world state a few steps after its birth: not lost before.
constexpr Step kBirthGraceSteps = 5;
// An actor judged hopeless (play_transport.cpp, move_actors) for this long gives up its role.
constexpr double kHopelessFor_s = 3.0;
// The ego's usual speed: its highest over this long (PlayRun::ego_slowed_down).
constexpr double kUsualSpeedWindow_s = 30.0;
// Closer to the start than this, and while the handover waits, the actors are aimed this far
// ahead (stage.hpp, aim_of): a plan that runs out of time would otherwise stop correcting.
constexpr double kAimHorizon_s = 4.0;

std::string fmt1(double x) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(1);
  os << x;
  return os.str();
}
}  // namespace

const char* to_string(PlayPhase p) {
  switch (p) {
    case PlayPhase::kWaiting: return "waiting";
    case PlayPhase::kPreparing: return "preparing";
    case PlayPhase::kCast: return "cast";
    case PlayPhase::kTransporting: return "transporting";
    case PlayPhase::kHandedOver: return "handed_over";
    case PlayPhase::kRunning: return "running";
    case PlayPhase::kDone: return "done";
    case PlayPhase::kFailed: return "failed";
  }
  return "unknown";
}

PlayRun::PlayRun(const PlayConfig& play, const PlaySetting& setting)
    : play_(play),
      staged_(play),
      setting_(setting),
      estimator_(StartTimeParams{setting.director.accel_memory_s}),
      ego_usual_speed_(kUsualSpeedWindow_s),
      roles_(play.roles.size()) {}

std::vector<VehicleId> PlayRun::holds() const {
  std::vector<VehicleId> out;
  for (const auto& [id, c] : sent_) {
    if (c.mode != ControlMode::kAutonomous) out.push_back(id);
  }
  for (const Role& r : roles_) {
    if (r.actor != kNoVehicle) out.push_back(r.actor);
  }
  return out;
}

std::vector<VehicleId> PlayRun::actors() const {
  std::vector<VehicleId> out;
  for (const Role& r : roles_) out.push_back(r.actor);
  return out;
}

const ObservedVehicle* PlayRun::find(const PlayInput& in, VehicleId id) const {
  if (id == kNoVehicle) return nullptr;
  auto it = std::lower_bound(in.world.begin(), in.world.end(), id,
                             [](const ObservedVehicle& v, VehicleId x) { return v.id < x; });
  return it != in.world.end() && it->id == id ? &*it : nullptr;
}

VehicleId PlayRun::held_back_for(VehicleId id) const {
  for (const auto& [waiting, follower] : letting_in_) {
    if (follower == id) return waiting;
  }
  return kNoVehicle;
}

std::size_t PlayRun::role_of(VehicleId id) const {
  std::size_t r = 0;
  while (r < roles_.size() && roles_[r].actor != id) ++r;
  return r;
}

bool PlayRun::is_cleared(VehicleId id) const {
  return std::find(cleared_.begin(), cleared_.end(), id) != cleared_.end();
}

bool PlayRun::open(const Role& r, const PlayInput& in) const {
  return r.actor == kNoVehicle || (r.hopeless_since_s >= 0.0 && in.ego.time_s - r.hopeless_since_s >= kHopelessFor_s);
}

ActorControl PlayRun::transported(double speed_mps, int lane) const {
  ActorControl c;
  c.mode = ControlMode::kTransported;
  c.play_id = play_.id;
  c.speed_mps = speed_mps;
  c.lane = lane;
  c.max_jerk_mps3 = setting_.director.max_jerk_mps3;
  return c;
}

ActorControl PlayRun::withdrawn() const {
  ActorControl c;
  c.mode = ControlMode::kWithdrawn;
  c.play_id = play_.id;
  return c;
}

ActorControl PlayRun::releasing() const {
  ActorControl c;
  c.mode = ControlMode::kReleasing;
  c.play_id = play_.id;
  c.max_jerk_mps3 = setting_.director.max_jerk_mps3;
  return c;
}

void PlayRun::command(VehicleId id, const ActorControl& c, Step step, PlayOutput& out) {
  auto it = sent_.find(id);
  if (it != sent_.end() && it->second == c) return;
  sent_[id] = c;
  const auto same = std::find_if(out.commands.begin(), out.commands.end(),
                                 [&](const ActorCommand& earlier) { return earlier.vehicle == id && earlier.step == step; });
  if (same != out.commands.end()) {
    same->control = c;
    return;
  }
  out.commands.push_back({id, step, c});
}

void PlayRun::report(const PlayInput& in, PlayOutput& out, std::string detail) {
  PlayReport r;
  r.play_id = play_.id;
  r.name = play_.name;
  r.phase = phase_;
  r.ego_s_m = in.ego.s_m;
  r.trigger1_s_m = play_.trigger1_s_m;
  r.trigger2_s_m = play_.trigger2_s_m;
  r.estimated_start_time_s = estimated_start_s_;
  r.created = created_count_;
  r.cleared = static_cast<std::uint16_t>(cleared_.size());
  for (const Role& role : roles_) {
    if (role.actor == kNoVehicle) continue;
    ++r.actors;
    r.position_error_m = std::max(r.position_error_m, std::abs(role.position_error_m));
    r.speed_error_mps = std::max(r.speed_error_mps, std::abs(role.speed_error_mps));
  }
  r.detail = std::move(detail);
  reported_estimate_s_ = estimated_start_s_;
  out.report = std::move(r);
}

PlayOutput PlayRun::step(const PlayInput& in) {
  PlayOutput out;
  estimator_.observe(in.ego.speed_mps, in.ego.accel_mps2, in.dt_s);
  ego_usual_speed_.observe(in.ego.time_s, in.ego.speed_mps);
  const double x = ego_progress(in.ego);
  const int dir = sign(in.ego.direction);
  const PlayPhase before = phase_;
  std::string waiting_for;  // beyond trigger point 2: what the start condition still lacks
  bool passed_trigger2 = false;  // in this step (reported at once: what was missing then)
  if (phase_ == PlayPhase::kWaiting && x >= dir * play_.trigger1_s_m && x < dir * play_.trigger2_s_m) {
    // Preparing starts with the first estimate; casting at the next step.
    phase_ = PlayPhase::kPreparing;
    const Prediction pred = estimator_.predict(dir * (play_.trigger2_s_m - in.ego.s_m), ego_leader(in));
    estimated_start_s_ = pred.time_s < 0.0 ? -1.0 : in.ego.time_s + pred.time_s;
    report(in, out, "trigger point 1 passed");
    first_report_ = false;
    return out;
  }
  if (phase_ == PlayPhase::kWaiting && x >= dir * play_.trigger2_s_m) {
    phase_ = PlayPhase::kFailed;
    report(in, out, "the ego was beyond trigger point 2 before the play could be prepared");
    first_report_ = false;
    return out;
  }
  switch (phase_) {
    case PlayPhase::kPreparing:
    case PlayPhase::kCast:
    case PlayPhase::kTransporting:
      if (x >= dir * play_.trigger2_s_m) {
        // Beyond trigger point 2: hand over as soon as the start condition holds; until then
        // (at most handover_wait_s) the actors keep closing on their places.
        if (trigger2_time_s_ < 0.0) {
          trigger2_time_s_ = in.ego.time_s;
          passed_trigger2 = true;
        }
        const std::string problems = start_problems(in);
        if (passed_trigger2) problems_at_trigger2_ = problems;
        if (problems.empty() || in.ego.time_s - trigger2_time_s_ >= play_.handover_wait_s - 1e-9) {
          hand_over(in, problems, out);
          return out;
        }
        waiting_for = problems;
      }
      prepare(in, out);
      break;
    case PlayPhase::kHandedOver:
    case PlayPhase::kRunning:
      run(in, out);
      return out;
    case PlayPhase::kDone:
    case PlayPhase::kFailed:
      finish_release(in, out);
      break;
    case PlayPhase::kWaiting:
      break;
  }
  if (out.report) return out;
  const bool estimate_moved = std::abs(estimated_start_s_ - reported_estimate_s_) > kEstimateReportThreshold_s;
  const bool progress_due = phase_ == PlayPhase::kTransporting &&
                            in.ego.time_s - last_progress_report_s_ >= kProgressReportInterval_s - 1e-9;
  if (first_report_ || before != phase_ || estimate_moved || progress_due || passed_trigger2) {
    if (progress_due || passed_trigger2) last_progress_report_s_ = in.ego.time_s;
    report(in, out, waiting_for.empty() ? "" : "beyond trigger point 2, waiting: " + waiting_for);
  }
  first_report_ = false;
  return out;
}

std::optional<LeaderAhead> PlayRun::ego_leader(const PlayInput& in) const {
  const ObservedVehicle* v = unpassable_leader(in.ego, in.world, setting_.lanes);
  if (v == nullptr) return std::nullopt;
  // An actor of this play ahead in the ego's lane goes to its start speed, and so does the queue
  // behind it: the leader is expected at that, not at the pace the actor's way there takes now.
  // (At its present speed, a truck slowed to lose ground on the ego made the ego expected ever
  // slower, the start later and the truck slower still: 35 km/h, and the ego passed it; and where
  // a car had cut in between them, both crawled at 9 m/s.)
  const int dir = sign(in.ego.direction);
  double nearest_p = std::numeric_limits<double>::infinity();
  double speed = v->speed_mps;
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const PlayRoleConfig& rc = play_.roles[r];
    const ObservedVehicle* a = find(in, roles_[r].actor);
    if (a == nullptr || rc.direction != Direction::kForward || !occupies(*a, in.ego.direction, in.ego.lane)) continue;
    const double p = dir * a->s_m;
    if (p < dir * v->s_m || p >= nearest_p) continue;
    nearest_p = p;
    speed = start_speed_mps(rc, in.ego.speed_mps);
  }
  return leader_ahead(in.ego, *v, speed);
}

void PlayRun::prepare(const PlayInput& in, PlayOutput& out) {
  const double distance = sign(in.ego.direction) * (play_.trigger2_s_m - in.ego.s_m);
  Prediction pred{0.0, in.ego.speed_mps};  // beyond trigger point 2: the start is now
  if (distance > 0.0) {
    pred = estimator_.predict(distance, ego_leader(in));
    if (pred.time_s < 0.0) {  // the ego stands: nothing can be timed, actors hold what they have
      estimated_start_s_ = -1.0;
      return;
    }
    estimated_start_s_ = in.ego.time_s + pred.time_s;
  }
  const Aim aim = aim_of(pred.time_s, play_.trigger2_s_m, pred.speed_mps, in.ego, kAimHorizon_s);
  // The lane the ego is in, or moving to.
  staged_ = staged_beside(play_, staged_lane(in), setting_.lanes);
  const std::vector<bool> restaged = restaged_roles(in);
  const std::vector<Slot> slots = slots_of(staged_, in.ego.direction, staged_lane(in), aim, setting_.lanes);
  // Actors that left the world (beyond the window) are lost: their roles are cast again.
  for (Role& r : roles_) {
    if (r.actor == kNoVehicle || find(in, r.actor) != nullptr) continue;
    if (r.created && in.step < r.cast_step + kBirthGraceSteps) continue;
    sent_.erase(r.actor);
    r = Role{};
  }
  const bool uncast = std::any_of(roles_.begin(), roles_.end(), [&](const Role& r) { return open(r, in); });
  std::string cast_detail;
  if (!restaged.empty() || (uncast && in.ego.time_s - last_cast_attempt_s_ >= kCastInterval_s - 1e-9)) {
    last_cast_attempt_s_ = in.ego.time_s;
    cast_detail = cast(in, slots, aim, pred.time_s, restaged, out);
  }
  const bool all_cast = std::none_of(roles_.begin(), roles_.end(), [](const Role& r) { return r.actor == kNoVehicle; });
  if (all_cast && phase_ == PlayPhase::kPreparing) {
    phase_ = PlayPhase::kCast;
  } else if (all_cast && phase_ == PlayPhase::kCast) {
    phase_ = PlayPhase::kTransporting;
  }
  move_actors(in, slots, aim, pred.time_s, out);
  clear_zones(in, slots, aim, pred.time_s, out);
  open_oncoming_gap(in, out);
  if (!cast_detail.empty()) report(in, out, "cast: " + cast_detail);
}

std::vector<bool> PlayRun::restaged_roles(const PlayInput& in) {
  const bool mirrored = mirrored_beside(play_, staged_lane(in), setting_.lanes);
  const bool flipped = mirrored_.has_value() && *mirrored_ != mirrored;
  mirrored_ = mirrored;
  if (!flipped) return {};
  std::vector<bool> restaged(roles_.size(), false);
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    const PlayRoleConfig& rc = play_.roles[r];
    restaged[r] = roles_[r].actor != kNoVehicle && rc.direction == Direction::kForward && rc.lane_offset != 0;
  }
  const bool any = std::find(restaged.begin(), restaged.end(), true) != restaged.end();
  return any ? restaged : std::vector<bool>{};
}

std::string PlayRun::start_problems(const PlayInput& in) {
  staged_ = staged_beside(play_, staged_lane(in), setting_.lanes);
  const int dir = sign(in.ego.direction);
  std::string problems;
  auto problem = [&](const std::string& p) { problems += (problems.empty() ? "" : "; ") + p; };
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    Role& role = roles_[r];
    const PlayRoleConfig& rc = staged_.roles[r];
    const ObservedVehicle* v = find(in, role.actor);
    if (v == nullptr) {
      problem(rc.name + ": no actor");
      continue;
    }
    const double ahead = dir * (v->s_m - in.ego.s_m);
    const double speed = start_speed_mps(rc, in.ego.speed_mps);
    role.position_error_m = ahead - rc.ahead_m;
    role.speed_error_mps = v->speed_mps - speed;
    // The lane the ego is in or moving to, as the slots were planned.
    const int lane = rc.direction == Direction::kForward ? staged_lane(in) + rc.lane_offset : rc.lane_offset;
    if (std::abs(role.position_error_m) > rc.position_tolerance_m) {
      problem(rc.name + ": " + fmt1(role.position_error_m) + " m from its start position");
    }
    if (std::abs(role.speed_error_mps) > rc.speed_tolerance_mps) {
      problem(rc.name + ": " + fmt1(role.speed_error_mps * 3.6) + " km/h from its start speed");
    }
    if (v->lane != lane && v->target_lane != lane) problem(rc.name + ": in lane " + std::to_string(v->lane) + ", not " + std::to_string(lane));
  }
  // The zones around where the ego is now.
  const std::vector<ZoneAtStart> zones = zones_of(staged_, in.ego.direction, staged_lane(in), in.ego.s_m, setting_.lanes);
  for (const ObservedVehicle& v : in.world) {
    if (role_of(v.id) < roles_.size()) continue;  // an actor
    if (zone_hit(zones, v, v.s_m) != nullptr) problem("vehicle " + std::to_string(v.id) + " in a clear zone");
  }
  return problems;
}

void PlayRun::hand_over(const PlayInput& in, const std::string& problems, PlayOutput& out) {
  handover_time_s_ = in.ego.time_s;
  const double waited_s = in.ego.time_s - trigger2_time_s_;
  const std::string after = waited_s > 1e-9 ? " (" + fmt1(waited_s) + " s beyond trigger point 2)" : "";
  // Cleared vehicles drive on as they like again.
  for (VehicleId id : cleared_) command(id, releasing(), in.step, out);
  if (!problems.empty()) {
    phase_ = PlayPhase::kFailed;
    release_all(in, out);
    // After the wait, first what was missing on passing trigger point 2, the cause: by the end of
    // the wait oncoming actors have moved on 40-50 m a second and read as far off.
    const std::string then = waited_s > 1e-9 && !problems_at_trigger2_.empty()
                                 ? " on passing trigger point 2: " + problems_at_trigger2_ + "; nor " +
                                       fmt1(waited_s) + " s beyond it"
                                 : after;
    report(in, out, "start condition not met" + then + ": " + problems);
    return;
  }
  phase_ = PlayPhase::kHandedOver;
  scripted_.assign(roles_.size(), ActorControl{});
  for (std::size_t r = 0; r < roles_.size(); ++r) {
    ActorControl c;
    c.mode = ControlMode::kControlled;
    c.play_id = play_.id;
    c.speed_mps = find(in, roles_[r].actor)->speed_mps;  // holds its speed until the script says otherwise
    c.accel_mps2 = c.decel_mps2 = 1.0;
    c.max_jerk_mps3 = setting_.director.max_jerk_mps3;
    scripted_[r] = c;
  }
  script_.emplace(staged_);
  for (std::size_t r = 0; r < roles_.size(); ++r) command(roles_[r].actor, scripted_[r], in.step, out);
  report(in, out, "every role in place" + after + "; the script starts");
  run(in, out);
}

void PlayRun::run(const PlayInput& in, PlayOutput& out) {
  const double since = in.ego.time_s - handover_time_s_;
  std::vector<const ObservedVehicle*> actors;
  for (const Role& r : roles_) actors.push_back(find(in, r.actor));
  const std::size_t started = script_->step(since, in.ego, actors, scripted_, setting_.lanes.of(in.ego.direction));
  for (std::size_t r = 0; r < roles_.size(); ++r) command(roles_[r].actor, scripted_[r], in.step, out);
  const bool ended = since >= play_.end_after_s ||
                     (play_.end_ego_beyond_s_m >= 0.0 &&
                      sign(in.ego.direction) * in.ego.s_m >= sign(in.ego.direction) * play_.end_ego_beyond_s_m);
  if (ended) {
    phase_ = PlayPhase::kDone;
    release_all(in, out);
    if (!out.report) report(in, out, "ended after " + fmt1(since) + " s; actors released");
    return;
  }
  if (started > 0 && phase_ == PlayPhase::kHandedOver) {
    phase_ = PlayPhase::kRunning;
    if (!out.report) report(in, out, "the script runs");
  }
}

void PlayRun::release_all(const PlayInput& in, PlayOutput& out) {
  release_until_s_ = in.ego.time_s + play_.release_s;
  for (const Role& r : roles_) {
    if (r.actor != kNoVehicle) command(r.actor, releasing(), in.step, out);
  }
}

void PlayRun::finish_release(const PlayInput& in, PlayOutput& out) {
  if (released_ || in.ego.time_s < release_until_s_ - 1e-9) return;
  released_ = true;
  for (const auto& [id, c] : std::map<VehicleId, ActorControl>(sent_)) {
    if (c.mode == ControlMode::kAutonomous || c.mode == ControlMode::kWithdrawn) continue;
    command(id, ActorControl{}, in.step, out);
  }
  for (Role& r : roles_) r.actor = kNoVehicle;
  cleared_.clear();
  lane_requests_.clear();
}

}  // namespace entourage::director
