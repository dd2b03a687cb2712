#include "generator/core/generator_core.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "behaviour/idm.hpp"
#include "traffic/driver_draw.hpp"

namespace entourage::generator {

namespace {
constexpr ServiceId kSelf{Role::kGenerator, 0};
// A vehicle not yet placed has no id among the others.
constexpr VehicleId kNoVehicle = std::numeric_limits<VehicleId>::max();
// Driver-stream labels: a driver's own stream is derived from the seed and its vehicle id.
constexpr std::uint64_t kDriverStreamLabel = 0x6472697665720000ULL;
// Places tried for a vehicle of the initial fill that found no room where it was drawn.
constexpr int kFillAttempts = 50;
// How long the generator remembers a birth the world does not show yet.
constexpr Step kBirthMemorySteps = 20;

// A new vehicle never starts closer than this share of the time gap behind another, even when
// the other is pulling away (where IDM's s* shrinks to s0).
constexpr double kMinTimeGapShare = 0.5;

// The gap a driver of `type` wants behind a leader: IDM's s*(v, v - v_leader) with the type's
// mean parameters, and at least half the time gap (what an entering vehicle needs, and what it
// must leave to a follower).
double wanted_gap_m(const VehicleTypeConfig& type, double speed_mps, double leader_speed_mps) {
  IdmParams p;
  p.time_gap_s = type.driver.time_gap_s.mean;
  p.max_accel_mps2 = type.driver.max_accel_mps2.mean;
  p.comfort_decel_mps2 = type.driver.comfort_decel_mps2.mean;
  p.min_gap_m = type.driver.min_gap_m.mean;
  return std::max(idm_desired_gap_m(p, speed_mps, speed_mps - leader_speed_mps),
                  p.min_gap_m + kMinTimeGapShare * speed_mps * p.time_gap_s);
}

double edge_position(Edge e, const WindowBounds& w) { return e == Edge::kRear ? w.rear_edge_m : w.front_edge_m; }
}  // namespace

GeneratorCore::GeneratorCore(const ScenarioConfig& scenario, std::uint64_t seed, GeneratorConfig config)
    : scenario_(scenario),
      config_(config),
      road_(scenario.road),
      forward_(make_stream(scenario, Direction::kForward)),
      backward_(make_stream(scenario, Direction::kBackward)),
      rng_(seed),
      seed_(seed),
      index_(scenario.road.lanes_forward, scenario.road.lanes_backward) {
  streams_.push_back({Direction::kForward, Edge::kRear, 0.0, rng_.exponential(1.0), {}});
  streams_.push_back({Direction::kForward, Edge::kFront, 0.0, rng_.exponential(1.0), {}});
  if (scenario.road.lanes_backward > 0) {
    streams_.push_back({Direction::kBackward, Edge::kFront, 0.0, rng_.exponential(1.0), {}});
  }
}

std::size_t GeneratorCore::queued() const {
  std::size_t n = 0;
  for (const auto& s : streams_) n += s.queue.size();
  return n;
}

StepOutput GeneratorCore::step(const StepInput& in) {
  StepOutput out;
  perceive(in);
  if (needs_fill(in)) fill(in, out);
  arrive(in);
  place(in, out);
  last_ego_ = in.ego;
  for (const Handoff& h : out.handoffs) recent_births_.push_back(h);
  return out;
}

bool GeneratorCore::needs_fill(const StepInput& in) const {
  if (!last_ego_) return true;
  const double expected = last_ego_->s_m + sign(last_ego_->direction) * last_ego_->speed_mps * scenario_.step_s;
  return std::abs(in.ego.s_m - expected) > config_.jump_threshold_m;
}

void GeneratorCore::perceive(const StepInput& in) {
  // Births become visible in the world one step after they are handed over (later in real time
  // if a message is late); until then the generator keeps them in mind itself.
  std::unordered_set<VehicleId> visible;
  for (const auto& o : in.world_prev) visible.insert(o.id);
  recent_births_.erase(std::remove_if(recent_births_.begin(), recent_births_.end(),
                                      [&](const Handoff& h) {
                                        return visible.count(h.vehicle.id) != 0 || h.step + kBirthMemorySteps < in.step;
                                      }),
                       recent_births_.end());
  const double dt = scenario_.step_s;
  index_.clear();
  for (const auto& o : in.world_prev) {
    add_to_index(index_, o.direction, o.lane, o.target_lane, o.id, o.progress_m() + o.speed_mps * dt, o.speed_mps,
                 o.accel_mps2, o.length_m);
  }
  for (const auto& h : recent_births_) {
    const Vehicle& v = h.vehicle;
    const double ahead = v.speed_mps * dt * static_cast<double>(in.step - h.step);
    add_to_index(index_, v.direction, v.lane, v.lane, v.id, v.progress_m() + ahead, v.speed_mps, 0.0, v.length_m);
  }
  add_to_index(index_, in.ego);
  index_.sort();
}

std::optional<std::pair<int, double>> GeneratorCore::find_room(Direction dir, double s_m, double speed_mps,
                                                               std::uint8_t type_index) const {
  const VehicleTypeConfig& type = scenario_.vehicle_types[type_index];
  const double p = sign(dir) * s_m;
  const int lanes = road_.lanes(dir);
  std::optional<std::pair<int, double>> best;
  for (int lane = 0; lane < (type.keep_right ? std::min(1, lanes) : lanes); ++lane) {
    const Occupant* leader = index_.leader(dir, lane, p, kNoVehicle);
    const Occupant* follower = index_.follower(dir, lane, p, kNoVehicle);
    double v = speed_mps;
    if (leader != nullptr) {
      const double gap = gap_between(*leader, p, type.length_m);
      if (gap < wanted_gap_m(type, v, leader->speed_mps)) v = std::min(v, leader->speed_mps);
      if (gap < wanted_gap_m(type, v, leader->speed_mps)) continue;
    }
    if (follower != nullptr) {
      const Occupant self{0, p, v, 0.0, type.length_m};
      if (gap_between(self, follower->progress_m, follower->length_m) < wanted_gap_m(type, follower->speed_mps, v)) {
        continue;
      }
    }
    if (!best || v > best->second + 1e-9) best = std::make_pair(lane, v);
  }
  return best;
}

Handoff GeneratorCore::birth(Direction dir, int lane, double s_m, double speed_mps, double desired_speed_mps,
                             std::uint8_t type_index, const WindowBounds& w, Step step, HandoffReason reason) {
  const VehicleTypeConfig& type = scenario_.vehicle_types[type_index];
  const VehicleId id = next_id_++;
  const std::uint64_t driver_seed = Random::derived(seed_, kDriverStreamLabel ^ id).next_u64();
  const DriverParams driver = draw_driver(type, desired_speed_mps, scenario_.road.speed_limit_mps, driver_seed, rng_);
  const Vehicle v = make_vehicle(id, type_index, type, dir, lane, s_m, speed_mps, driver);
  const Region region = w.region_of(s_m);
  const Role to = region == Region::kInner ? Role::kMicro : Role::kMeso;
  add_to_index(index_, dir, lane, lane, id, v.progress_m(), speed_mps, 0.0, v.length_m);
  index_.sort();
  return make_handoff(v, step, kSelf, to, region, reason);
}

void GeneratorCore::fill(const StepInput& in, StepOutput& out) {
  ++counters_.fills;
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  for (Direction dir : {Direction::kForward, Direction::kBackward}) {
    const StreamModel& m = model(dir);
    if (road_.lanes(dir) == 0 || m.density_per_m() <= 0.0) continue;
    // The window gets the stream's expected number of vehicles, k L (rounded), at positions that
    // are uniform given that number (a Poisson process conditioned on its count: every run starts
    // with the demanded density rather than a random one). They are placed from the front of the
    // window (in the direction of travel) backwards, so that each one's leader is already there;
    // a position too close to the vehicle ahead in every lane moves back to the nearest room.
    const double front_p = dir == Direction::kForward ? w.front_edge_m : -w.rear_edge_m;
    const double back_p = dir == Direction::kForward ? w.rear_edge_m : -w.front_edge_m;
    const auto count = static_cast<std::size_t>(std::llround(m.density_per_m() * (front_p - back_p)));
    std::vector<double> points(count);
    for (double& p : points) p = rng_.uniform(back_p, front_p);
    std::sort(points.begin(), points.end(), std::greater<>());
    std::size_t homeless = 0;
    for (const double p : points) {
      const SpeedDraw d = m.draw_space_mean(rng_);
      const auto spot = fill_spot(dir, p, d.speed_mps, d.type_index);
      if (!spot || spot->progress_m <= back_p) {
        ++homeless;
        continue;
      }
      out.handoffs.push_back(birth(dir, spot->lane, sign(dir) * spot->progress_m, spot->speed_mps, d.speed_mps,
                                   d.type_index, w, in.step, HandoffReason::kInitialFill));
      ++counters_.filled;
    }
    // A vehicle pushed out at the back by those ahead of it goes to another place with room.
    for (; homeless > 0; --homeless) {
      const SpeedDraw d = m.draw_space_mean(rng_);
      std::optional<Spot> spot;
      for (int attempt = 0; attempt < kFillAttempts && (!spot || spot->progress_m <= back_p); ++attempt) {
        spot = fill_spot(dir, rng_.uniform(back_p, front_p), d.speed_mps, d.type_index);
      }
      if (!spot || spot->progress_m <= back_p) {
        ++counters_.fill_dropped;
        continue;
      }
      out.handoffs.push_back(birth(dir, spot->lane, sign(dir) * spot->progress_m, spot->speed_mps, d.speed_mps,
                                   d.type_index, w, in.step, HandoffReason::kInitialFill));
      ++counters_.filled;
    }
  }
}

double GeneratorCore::room_behind(Direction dir, int lane, double progress_m, double speed_mps,
                                  const VehicleTypeConfig& type) const {
  // Move back until the vehicle ahead (which may change as we move) is far enough.
  double p = progress_m;
  for (const Occupant* leader = index_.leader(dir, lane, p, kNoVehicle); leader != nullptr;
       leader = index_.leader(dir, lane, p, kNoVehicle)) {
    const double room = leader->progress_m - 0.5 * (leader->length_m + type.length_m) -
                        wanted_gap_m(type, speed_mps, leader->speed_mps);
    if (p <= room) break;
    p = room;
  }
  return p;
}

std::optional<GeneratorCore::Spot> GeneratorCore::fill_spot(Direction dir, double progress_m, double speed_mps,
                                                          std::uint8_t type_index) const {
  const VehicleTypeConfig& type = scenario_.vehicle_types[type_index];
  const int lanes = road_.lanes(dir);
  std::optional<Spot> best;
  for (int lane = 0; lane < (type.keep_right ? std::min(1, lanes) : lanes); ++lane) {
    // At its desired speed, or caught up behind a slower vehicle ahead at that one's speed
    // (stationary traffic has such pairs), whichever needs the smaller move backwards.
    Spot spot{lane, room_behind(dir, lane, progress_m, speed_mps, type), speed_mps};
    if (const Occupant* leader = index_.leader(dir, lane, progress_m, kNoVehicle);
        leader != nullptr && leader->speed_mps < speed_mps) {
      const double p = room_behind(dir, lane, progress_m, leader->speed_mps, type);
      if (p > spot.progress_m + 1e-9) spot = Spot{lane, p, leader->speed_mps};
    }
    const Occupant* follower = index_.follower(dir, lane, spot.progress_m, kNoVehicle);
    if (follower != nullptr) {
      const Occupant self{0, spot.progress_m, spot.speed_mps, 0.0, type.length_m};
      if (gap_between(self, follower->progress_m, follower->length_m) <
          wanted_gap_m(type, follower->speed_mps, spot.speed_mps)) {
        continue;  // an existing vehicle behind (a refill after a jump) leaves no room here
      }
    }
    if (!best || spot.progress_m > best->progress_m + 1e-9) best = spot;
  }
  return best;
}

double GeneratorCore::rate(const Stream& s, double u) const {
  const StreamModel& m = model(s.dir);
  if (s.dir == Direction::kBackward) return m.rate_oncoming_per_s(u);
  return s.edge == Edge::kRear ? m.rate_rear_per_s(u) : m.rate_front_per_s(u);
}

SpeedDraw GeneratorCore::draw(const Stream& s, double u) {
  const StreamModel& m = model(s.dir);
  if (s.dir == Direction::kBackward) return m.draw_oncoming(rng_, u);
  return s.edge == Edge::kRear ? m.draw_rear(rng_, u) : m.draw_front(rng_, u);
}

void GeneratorCore::arrive(const StepInput& in) {
  const double u = std::max(0.0, in.ego.speed_mps);
  for (Stream& s : streams_) {
    s.accumulated += rate(s, u) * scenario_.step_s;
    while (s.accumulated >= s.next) {
      s.accumulated -= s.next;
      s.next = rng_.exponential(1.0);
      const SpeedDraw d = draw(s, u);
      s.queue.push_back({d.type_index, d.speed_mps});
      ++counters_.arrivals;
      if (s.queue.size() > config_.max_queue) s.queue.pop_front();
    }
  }
}

void GeneratorCore::place(const StepInput& in, StepOutput& out) {
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  const double u = std::max(0.0, in.ego.speed_mps);
  for (Stream& s : streams_) {
    const double edge_s = edge_position(s.edge, w);
    while (!s.queue.empty()) {
      const Pending& next = s.queue.front();
      const bool from_behind = s.dir == Direction::kForward && s.edge == Edge::kRear;
      auto room = find_room(s.dir, edge_s, next.speed_mps, next.type_index);
      // From behind, a vehicle that cannot go faster than the window would never enter it: wait.
      if (!room || (from_behind && room->second <= u)) break;
      out.handoffs.push_back(
          birth(s.dir, room->first, edge_s, room->second, next.speed_mps, next.type_index, w, in.step,
                HandoffReason::kBirth));
      s.queue.pop_front();
      ++counters_.placed;
    }
    counters_.waited_steps += s.queue.size();
  }
}

}  // namespace entourage::generator
