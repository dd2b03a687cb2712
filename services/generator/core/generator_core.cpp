#include "generator/core/generator_core.hpp"

#include <algorithm>
#include <cmath>

#include "traffic/entry.hpp"

namespace entourage::generator {

namespace {
constexpr ServiceId kSelf{Role::kGenerator, 0};
// Seed label of each driver's own stream (with its vehicle id); the stream observations' seeds:
// observation_seed (traffic/observed_stream.hpp).
constexpr std::uint64_t kDriverStreamLabel = 0x6472697665720000ULL;
// How long the generator remembers a birth the world does not show yet.
constexpr Step kBirthMemorySteps = 20;
// The direction whose arrivals the regulation scales: the ego's (services/generator/README.md,
// *Regulation*).
constexpr Direction kRegulatedDirection = Direction::kForward;

double edge_position(Edge e, const WindowBounds& w) { return e == Edge::kRear ? w.rear_edge_m : w.front_edge_m; }

ObservedStream observe(const ScenarioConfig& sc, Direction dir, const GeneratorConfig& config, std::uint64_t seed) {
  return ObservedStream(sc, dir, config.observation, observation_seed(seed, dir));
}
}  // namespace

GeneratorCore::GeneratorCore(const ScenarioConfig& scenario, std::uint64_t seed, GeneratorConfig config)
    : scenario_(scenario),
      config_(config),
      road_(scenario.road),
      rng_(seed),
      seed_(seed),
      forward_(observe(scenario, Direction::kForward, config, seed)),
      backward_(observe(scenario, Direction::kBackward, config, seed)),
      index_(scenario.road.lanes_forward, scenario.road.lanes_backward) {
  edges_.push_back({Direction::kForward, Edge::kRear, Entrance::kRear, 0.0, rng_.exponential(1.0), {}});
  edges_.push_back({Direction::kForward, Edge::kFront, Entrance::kFront, 0.0, rng_.exponential(1.0), {}});
  if (scenario.road.lanes_backward > 0) {
    edges_.push_back({Direction::kBackward, Edge::kFront, Entrance::kOncoming, 0.0, rng_.exponential(1.0), {}});
  }
}

std::size_t GeneratorCore::queued() const {
  std::size_t n = 0;
  for (const auto& e : edges_) n += e.queue.size();
  return n;
}

StepOutput GeneratorCore::step(const StepInput& in) {
  StepOutput out;
  for (const Handoff& h : inbox_.accept(in.handoffs)) adopt_left_ahead(h.vehicle);
  counters_.commands_applied += zone_.apply(in.commands);
  perceive(in);
  zone_.move(index_, scenario_.step_s);
  index_world(in);
  if (needs_fill(in)) fill(in, out);
  arrive(in);
  place(in, out);
  hand_over(in, out);
  last_ego_ = in.ego;
  for (const Handoff& h : out.handoffs) {
    if (h.from == kSelf && h.to_role != Role::kNone) recent_births_.push_back(h);
  }
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
  // (A few births at a time against the world: a scan, not a set of the whole world's ids built
  // at every step, which was a tenth of the generator's cost in allocations.)
  const auto visible = [&](VehicleId id) {
    return std::any_of(in.world_prev.begin(), in.world_prev.end(), [&](const ObservedVehicle& o) { return o.id == id; });
  };
  recent_births_.erase(std::remove_if(recent_births_.begin(), recent_births_.end(),
                                      [&](const Handoff& h) {
                                        return h.step + kBirthMemorySteps < in.step || visible(h.vehicle.id);
                                      }),
                       recent_births_.end());
  index_world(in);
}

void GeneratorCore::index_world(const StepInput& in) {
  const double dt = scenario_.step_s;
  index_.clear();
  for (const auto& o : in.world_prev) {
    if (zone_.owns(o.id)) continue;  // the zone's own state is newer
    add_to_index(index_, o.direction, o.lane, o.target_lane, o.id, o.progress_m() + o.speed_mps * dt, o.speed_mps,
                 o.accel_mps2, o.length_m);
  }
  for (const Vehicle& v : zone_.vehicles().vehicles()) {
    add_to_index(index_, v.direction, v.lane, v.target_lane(), v.id, v.progress_m(), v.speed_mps, v.accel_mps2,
                 v.length_m);
  }
  for (const auto& h : recent_births_) {
    const Vehicle& v = h.vehicle;
    const double ahead = v.speed_mps * dt * static_cast<double>(in.step - h.step);
    add_to_index(index_, v.direction, v.lane, v.lane, v.id, v.progress_m() + ahead, v.speed_mps, 0.0, v.length_m);
  }
  if (!scenario_.ego.transparent) add_to_index(index_, in.ego);
  index_.sort();
}

bool GeneratorCore::room_ahead(Direction dir, int lane, double p, const Vehicle& v) const {
  const Occupant* leader = index_.leader(dir, lane, p, kNoVehicle);
  return leader == nullptr ||
         gap_between(*leader, p, v.length_m) >= wanted_gap_m(v.driver.car_following.idm, v.speed_mps, leader->speed_mps);
}

const Occupant* GeneratorCore::crowding_follower(Direction dir, int lane, double p, const Vehicle& v) const {
  const Occupant* follower = index_.follower(dir, lane, p, kNoVehicle);
  if (follower == nullptr) return nullptr;
  const Occupant self{kNoVehicle, p, v.speed_mps, 0.0, v.length_m};
  const double wanted = wanted_gap_m(v.driver.car_following.idm, follower->speed_mps, v.speed_mps);
  return gap_between(self, follower->progress_m, follower->length_m) < wanted ? follower : nullptr;
}

bool GeneratorCore::fits(Direction dir, int lane, double p, const Vehicle& v) const {
  return room_ahead(dir, lane, p, v) && crowding_follower(dir, lane, p, v) == nullptr;
}

Vehicle GeneratorCore::make(const Vehicle& model, Direction dir, int lane, double progress_m, double speed_mps) {
  Vehicle v = model;
  v.id = next_id_++;
  v.direction = dir;
  v.lane = lane;
  v.s_m = sign(dir) * progress_m;
  v.speed_mps = speed_mps;
  v.accel_mps2 = 0.0;
  v.handoff_sequence = 0;
  v.lane_change = LaneChangeState{};
  v.lane_change.from_lane = v.lane_change.to_lane = lane;
  v.lane_change.duration_s = v.driver.lane_change_duration_s;
  v.overtaking = OvertakingState{};
  v.requested_lane = -1;
  v.hdm_errors = HdmErrors{};
  v.hdm_memory = HdmMemory{};
  v.driver.rng_state = Random::derived(seed_, kDriverStreamLabel ^ v.id).next_u64();
  add_to_index(index_, dir, lane, lane, v.id, progress_m, speed_mps, 0.0, v.length_m);
  index_.sort();
  return v;
}

Handoff GeneratorCore::birth(const Vehicle& model, Direction dir, int lane, double progress_m, double speed_mps,
                             const WindowBounds& w, Step step, HandoffReason reason) {
  const Vehicle v = make(model, dir, lane, progress_m, speed_mps);
  const Region region = w.region_of(v.s_m);
  const Role to = region == Region::kInner ? Role::kMicro : Role::kMeso;
  return make_handoff(v, step, kSelf, to, region, reason);
}

void GeneratorCore::fill(const StepInput& in, StepOutput& out) {
  ++counters_.fills;
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  for (Direction dir : {Direction::kForward, Direction::kBackward}) {
    const ObservedStream& stream = this->stream(dir);
    if (stream.empty()) continue;
    // A stretch of the observed stream as long as the window, laid from the window's rear end
    // in the direction of travel; vehicles that would overlap the ego (or, after a jump, vehicles
    // already there) are left out.
    // Within the stretch only overlapping pairs are left out (the stream is otherwise consistent
    // in itself); against what was there before it, every vehicle needs its room.
    // In the ego's direction it reaches on into the front zone.
    const double back_p = dir == Direction::kForward ? w.rear_edge_m : -w.front_edge_m;
    const double length = w.front_edge_m - w.rear_edge_m + (dir == Direction::kForward ? config_.front_zone_m : 0.0);
    std::vector<StreamVehicle> stretch = stream.stretch(rng_, length, config_.fill_candidates);
    counters_.fill_overlapping += remove_overlapping(stretch);
    std::vector<StreamVehicle> accepted;
    for (const StreamVehicle& sv : stretch) {
      if (fits(dir, sv.vehicle.lane, back_p + sv.offset_m, sv.vehicle)) {
        accepted.push_back(sv);
      } else {
        ++counters_.fill_skipped;
      }
    }
    for (const StreamVehicle& sv : accepted) {
      const double p = back_p + sv.offset_m;
      if (dir == Direction::kForward && p > w.front_edge_m) {
        zone_.add(make(sv.vehicle, dir, sv.vehicle.lane, p, sv.vehicle.speed_mps));
        ++counters_.ahead;
        continue;
      }
      out.handoffs.push_back(
          birth(sv.vehicle, dir, sv.vehicle.lane, p, sv.vehicle.speed_mps, w, in.step, HandoffReason::kInitialFill));
      ++counters_.filled;
    }
  }
}

double GeneratorCore::rate(const EdgeStream& s, double u) const {
  const ObservedStream& stream = this->stream(s.dir);
  if (s.dir == Direction::kBackward) return stream.rate_oncoming_per_s(u);
  return s.edge == Edge::kRear ? stream.rate_rear_per_s(u) : stream.rate_front_per_s(u);
}

double GeneratorCore::regulation(const StepInput& in) const {
  const double gain = scenario_.demand_regulation_gain;
  if (gain <= 0.0) return 1.0;
  // The ego's direction in the outer regions only, by default: the ego gathers vehicles around
  // itself (those it holds up, those it follows), so the inner region holds more than the stream's
  // density, while the outer regions hold what the stream does (whole-road measurement: README,
  // *Regulation*). The oncoming direction is not regulated: its vehicles cross the window in well
  // under a minute, so its count does not wander, and counted against the stream's density the
  // window held fewer of them than the density says, so that the regulation raised the oncoming
  // flow 4 % above the demand (72 drives: met 1.042 of the prediction, 0.994 without it).
  const Direction d = kRegulatedDirection;
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  const bool whole = scenario_.demand_regulation_whole_window;
  std::size_t present = 0;
  const auto count = [&](Direction dir, double s_m) {
    if (dir != d) return;
    const Region r = w.region_of(s_m);
    if (r == Region::kOuterRear || r == Region::kOuterFront || (whole && r == Region::kInner)) ++present;
  };
  for (const auto& o : in.world_prev) {
    if (!zone_.owns(o.id)) count(o.direction, o.s_m);
  }
  for (const auto& h : recent_births_) count(h.vehicle.direction, h.vehicle.s_m);
  const double outer_m = (w.front_edge_m - w.inner_front_m) + (w.inner_rear_m - w.rear_edge_m);
  const double counted_m = whole ? w.front_edge_m - w.rear_edge_m : outer_m;
  const double expected = stream(d).density_per_m() * counted_m;
  if (!(expected > 0.0)) return 1.0;
  const double deficit = (expected - static_cast<double>(present)) / expected;
  return std::clamp(1.0 + gain * deficit, 0.0, 1.0 + gain);
}

void GeneratorCore::arrive(const StepInput& in) {
  const double u = std::max(0.0, in.ego.speed_mps);
  const double regulated = regulation(in);
  for (EdgeStream& s : edges_) {
    const ObservedStream& stream = this->stream(s.dir);
    if (stream.empty()) continue;
    const double plain = rate(s, u) * scenario_.step_s;
    const double hazard = s.dir == kRegulatedDirection ? plain * regulated : plain;
    counters_.expected_plain_at[static_cast<std::size_t>(s.entrance)] += plain;
    counters_.expected_regulated_at[static_cast<std::size_t>(s.entrance)] += hazard;
    s.accumulated += hazard;
    while (s.accumulated >= s.next) {
      s.accumulated -= s.next;
      s.next = rng_.exponential(1.0);
      const Platoon& p = s.dir == Direction::kBackward ? stream.draw_oncoming(rng_, u)
                         : s.edge == Edge::kRear        ? stream.draw_rear(rng_, u)
                                                        : stream.draw_front(rng_, u);
      s.queue.push_back({p, 0});
      ++counters_.arrivals;
      ++counters_.arrivals_at[static_cast<std::size_t>(s.entrance)];
      counters_.members_at[static_cast<std::size_t>(s.entrance)] += p.members.size();
      if (s.queue.size() > config_.max_queue) {
        s.queue.pop_front();
        ++counters_.dropped;
      }
    }
  }
}

bool GeneratorCore::place_one_by_one(const EdgeStream& s, Pending& pending, double u, const WindowBounds& w, Step step,
                                     StepOutput& out) {
  const double edge_p = sign(s.dir) * edge_position(s.edge, w);
  const bool from_behind = s.dir == Direction::kForward && s.edge == Edge::kRear;
  while (pending.next_member < pending.platoon.members.size()) {
    const Vehicle& model = pending.platoon.members[pending.next_member].vehicle;
    // From behind, the platoon reaches the window at its leader's speed: a member the snapshot
    // caught slower than the window (dropping back from its leader for a moment) enters at it.
    // Whole-road drives cross the rear edge's moving point at the moving-observer rate counted
    // with every member (entourage-bench-catchups); dropping such members lost 8 % of them.
    const bool raised = from_behind && model.speed_mps <= u;
    const double speed_mps = raised ? pending.platoon.speed_mps : model.speed_mps;
    const auto room = find_entry(index_, s.dir, edge_p, speed_mps, scenario_.vehicle_types[model.type_index],
                                 model.driver.car_following.idm, model.lane,
                                 from_behind ? EntryPolicy::kMatchLeader : EntryPolicy::kOwnSpeed);
    // From behind, a vehicle held below the window's speed by the one ahead would not reach it yet.
    if (!room || (from_behind && room->speed_mps <= u)) return false;
    out.handoffs.push_back(birth(model, s.dir, room->lane, edge_p, room->speed_mps, w, step, HandoffReason::kBirth));
    if (raised) ++counters_.at_leader_speed;
    ++counters_.placed;
    ++counters_.placed_at[static_cast<std::size_t>(s.entrance)];
    ++pending.next_member;
  }
  return true;
}

bool GeneratorCore::platoon_fits(const Platoon& platoon, Direction dir, int lane, double leader_p,
                                 std::vector<VehicleId>& in_the_way) const {
  in_the_way.clear();
  const StreamVehicle& tail = platoon.members.back();
  const StreamVehicle& head = platoon.members.front();
  const double tail_p = leader_p - tail.offset_m;
  // Whatever follows it (the window's vehicles near the edge) and whatever leads it must have room;
  // a zone vehicle crowding its tail is inside its span, judged below.
  const Occupant* crowding = crowding_follower(dir, lane, tail_p, tail.vehicle);
  if ((crowding != nullptr && !zone_.owns(crowding->id)) || !room_ahead(dir, lane, leader_p, head.vehicle)) return false;
  // Zone vehicles within its span: faster ones are taken to have passed it (they leave, far ahead
  // of the driver); a slower one (not yet reached by the edge) makes the lane unusable.
  const double from = tail_p - tail.vehicle.length_m - config_.front_entry_margin_m;
  const double to = leader_p + head.vehicle.length_m + config_.front_entry_margin_m;
  for (const Occupant& o : index_.lane(dir, lane)) {
    if (o.progress_m < from || o.progress_m > to) continue;
    if (!zone_.owns(o.id) || o.speed_mps <= platoon.speed_mps) return false;
    in_the_way.push_back(o.id);
  }
  return true;
}

bool GeneratorCore::place_from_ahead(const EdgeStream& s, const Pending& pending, const WindowBounds& w) {
  // A slow platoon lies ahead of the window; the edge reaches its last vehicle first. It joins the
  // front zone whole, its last vehicle just beyond the edge, in its own lane or another one (only
  // the right lane if a member keeps right); its vehicles enter the window as the edge reaches
  // them (hand_over).
  const Platoon& platoon = pending.platoon;
  const double leader_p = w.front_edge_m + config_.front_entry_margin_m + platoon.members.back().offset_m;
  const int own = platoon.members.front().vehicle.lane;
  bool keep_right = false;
  for (const StreamVehicle& m : platoon.members) keep_right |= scenario_.vehicle_types[m.vehicle.type_index].keep_right;
  const int lanes = keep_right ? 1 : scenario_.road.lanes(s.dir);
  std::vector<VehicleId> in_the_way;
  for (int k = 0; k < lanes; ++k) {
    const int lane = k == 0 ? std::min(own, lanes - 1) : (k <= own ? k - 1 : k);
    if (!platoon_fits(platoon, s.dir, lane, leader_p, in_the_way)) continue;
    for (VehicleId id : in_the_way) {
      for (Vehicle& v : zone_.remove(id)) passed_.push_back(std::move(v));
    }
    for (const StreamVehicle& m : platoon.members) {
      add_to_zone(make(m.vehicle, s.dir, lane, leader_p - m.offset_m, m.vehicle.speed_mps));
    }
    index_.sort();  // the next platoon in the queue sees this one
    return true;
  }
  return false;
}

void GeneratorCore::adopt_left_ahead(const Vehicle& v) {
  zone_.add(v, std::max(v.speed_mps, stream(v.direction).typical_speed_mps(v)));
}

void GeneratorCore::add_to_zone(const Vehicle& v) {
  zone_.add(v);
  add_to_index(index_, v.direction, v.lane, v.lane, v.id, v.progress_m(), v.speed_mps, 0.0, v.length_m);
  ++counters_.ahead;
}

void GeneratorCore::hand_over(const StepInput& in, StepOutput& out) {
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  const auto reached = zone_.reached_by(w.front_edge_m);
  for (const Vehicle& v : zone_.vehicles().vehicles()) out.states.push_back({v, w.region_of(v.s_m)});
  for (const Vehicle& v : reached) {
    out.states.push_back({v, w.region_of(v.s_m)});
    Handoff h = make_handoff(v, in.step, kSelf, Role::kMeso, Region::kOuterFront, HandoffReason::kBirth);
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
    ++counters_.placed;
    ++counters_.placed_at[static_cast<std::size_t>(Entrance::kFront)];
  }
  std::vector<Vehicle> leaving = zone_.beyond(w.front_edge_m + config_.front_zone_limit_m);
  counters_.made_way += passed_.size();
  for (Vehicle& v : passed_) leaving.push_back(std::move(v));
  passed_.clear();
  for (const Vehicle& v : leaving) {
    Handoff h = make_handoff(v, in.step, kSelf, Role::kNone, Region::kOutside, HandoffReason::kLeftWindow);
    inbox_.note_sent(h);
    out.handoffs.push_back(std::move(h));
    ++counters_.left_ahead;
  }
  std::sort(out.states.begin(), out.states.end(),
            [](const VehicleReport& a, const VehicleReport& b) { return a.id < b.id; });
}

void GeneratorCore::place(const StepInput& in, StepOutput& out) {
  const WindowBounds w = WindowBounds::around(in.ego.s_m, scenario_.window);
  const double u = std::max(0.0, in.ego.speed_mps);
  for (EdgeStream& s : edges_) {
    const bool ahead = s.dir == Direction::kForward && s.edge == Edge::kFront;
    // Every waiting platoon gets its turn, in the order they arrived: one that cannot enter yet
    // does not hold up those behind it, which may find room in another lane (as faster traffic
    // passes a slow vehicle before the edge reaches either).
    auto waiting = s.queue.begin();  // those still waiting are moved up, in order, in place
    for (auto it = s.queue.begin(); it != s.queue.end(); ++it) {
      const bool done = ahead ? place_from_ahead(s, *it, w) : place_one_by_one(s, *it, u, w, in.step, out);
      if (done) continue;
      if (waiting != it) *waiting = std::move(*it);
      ++waiting;
    }
    s.queue.erase(waiting, s.queue.end());
    counters_.waited_steps += s.queue.size();
  }
}

}  // namespace entourage::generator
