#include "traffic/observed_stream.hpp"

#include <algorithm>
#include <cmath>

#include "core/ids.hpp"
#include "traffic/road_sim.hpp"

namespace entourage {

namespace {
constexpr std::uint64_t kObservationLabel = 0x6f62736572766500ULL;
}  // namespace

std::uint64_t generator_seed(std::uint64_t run_seed) {
  return Random::derived(run_seed, static_cast<std::uint64_t>(Role::kGenerator)).next_u64();
}

std::uint64_t observation_seed(std::uint64_t generator_seed, Direction dir) {
  return Random::derived(generator_seed, kObservationLabel + (dir == Direction::kForward ? 0 : 1)).next_u64();
}

void cut_into_platoons(const std::vector<StreamVehicle>& snap, int lanes, const PlatoonRule& rule,
                       std::vector<Platoon>* out) {
  for (int lane = 0; lane < lanes; ++lane) {
    Platoon current;
    double leader_offset = 0.0;
    double previous_rear = 0.0;
    for (auto it = snap.rbegin(); it != snap.rend(); ++it) {
      const StreamVehicle& v = *it;
      if (v.vehicle.lane != lane) continue;
      const double front = v.offset_m + 0.5 * v.vehicle.length_m;
      const bool close = previous_rear - front < rule.headway_s * std::max(v.vehicle.speed_mps, 1.0);
      const bool keeps_up = v.vehicle.speed_mps >= current.speed_mps - rule.speed_tolerance_mps;
      const bool joins = !current.members.empty() && close && keeps_up;
      if (!joins) {
        if (!current.members.empty()) out->push_back(std::move(current));
        current = Platoon{v.vehicle.speed_mps, {}};
        leader_offset = v.offset_m;
      }
      current.members.push_back({leader_offset - v.offset_m, v.vehicle});
      previous_rear = v.offset_m - 0.5 * v.vehicle.length_m;
    }
    if (!current.members.empty()) out->push_back(std::move(current));
  }
}

ObservedStream::ObservedStream(const ScenarioConfig& scenario, Direction dir, const StreamObservation& how,
                               std::uint64_t seed) {
  flow_ = scenario.flow(dir).flow_veh_per_s;
  const int lanes = scenario.road.lanes(dir);
  if (flow_ <= 0.0 || lanes == 0) return;
  RoadSimConfig cfg;
  cfg.length_m = how.road_length_m;
  RoadSim sim(scenario, dir, cfg, seed);
  sampled_length_m_ = how.road_length_m - how.settled_from_m;
  double next_snapshot = how.warmup_s;
  double carried = 0.0;  // the snapshots' flow times their length, each vehicle at its own speed
  double carried_by_all = 0.0;  // the same with the vehicles in the middle of an overtaking
  while (snapshots_.size() < static_cast<std::size_t>(how.snapshots)) {
    sim.step();
    if (sim.time_s() + 1e-9 < next_snapshot) continue;
    next_snapshot += how.snapshot_every_s;
    std::vector<StreamVehicle> snap;
    for (const Vehicle& v : sim.fleet().vehicles()) {
      if (v.direction != dir) continue;
      const double along_m = dir == Direction::kForward ? v.s_m : how.road_length_m - v.s_m;
      if (along_m < how.settled_from_m || along_m >= how.road_length_m) continue;
      crossing_speeds_.add(v.speed_mps);
      carried_by_all += v.speed_mps;
      // Vehicles in the middle of an overtaking are left out of the snapshots (not of the rates): a
      // window cannot start with a vehicle beside the one it passes.
      if (v.overtaking.active() || v.lane >= lanes) continue;
      snap.push_back({along_m - how.settled_from_m, v});
    }
    std::sort(snap.begin(), snap.end(), [](const auto& a, const auto& b) { return a.offset_m < b.offset_m; });
    for (const StreamVehicle& sv : snap) {
      note_speed_ratio(sv.vehicle);
      vehicle_speeds_.add(sv.vehicle.speed_mps);
      carried += sv.vehicle.speed_mps;
    }
    cut_into_platoons(snap, lanes, how.platoon, &platoons_);
    snapshots_.push_back(std::move(snap));
  }
  for (auto& pairs : speed_ratio_by_desired_) std::sort(pairs.begin(), pairs.end());
  const double observed_length = sampled_length_m_ * static_cast<double>(snapshots_.size());
  vehicle_speeds_.finish();
  crossing_speeds_.finish();
  // The same flow counted the way the platoons enter (each member at its leader's speed). Each
  // density is scaled so that what it carries is the demanded flow: the vehicles' (what the
  // window's regulation aims at and the catch-up rates count) with their own speeds, the platoons'
  // (the arrivals) with theirs.
  double carried_by_platoons = 0.0;
  for (const auto& p : platoons_) {
    carried_by_platoons += static_cast<double>(p.members.size()) * p.speed_mps;
    platoon_speeds_.add(p.speed_mps);
  }
  platoon_speeds_.finish();
  sample_flow_ = carried / observed_length;
  const auto scaled = [&](double count, double carried_sum) {
    return carried_sum > 0.0 ? count * flow_ / carried_sum : count / observed_length;
  };
  vehicle_density_ = scaled(static_cast<double>(vehicle_speeds_.size()), carried);
  crossing_density_ = scaled(static_cast<double>(crossing_speeds_.size()), carried_by_all);
  platoon_density_ = scaled(static_cast<double>(platoons_.size()), carried_by_platoons);
}

void ObservedStream::note_speed_ratio(const Vehicle& v) {
  const double desired = v.driver.desired_speed_mps();
  if (!(desired > 0.0)) return;
  if (speed_ratio_by_desired_.size() <= v.type_index) speed_ratio_by_desired_.resize(v.type_index + 1u);
  speed_ratio_by_desired_[v.type_index].emplace_back(desired, v.speed_mps / desired);
}

double ObservedStream::typical_speed_mps(const Vehicle& v) const {
  const double desired = v.driver.desired_speed_mps();
  if (v.type_index >= speed_ratio_by_desired_.size()) return desired;
  const auto& pairs = speed_ratio_by_desired_[v.type_index];
  if (pairs.empty()) return desired;
  // The kTypicalNeighbours closest in desired speed: a window of that many around the place
  // `desired` would be sorted in, moved inside the range.
  const auto at = std::lower_bound(pairs.begin(), pairs.end(), std::make_pair(desired, 0.0)) - pairs.begin();
  const auto n = static_cast<std::ptrdiff_t>(pairs.size());
  const auto count = std::min<std::ptrdiff_t>(kTypicalNeighbours, n);
  const auto first = std::clamp<std::ptrdiff_t>(at - count / 2, 0, n - count);
  double ratio_sum = 0.0;
  for (std::ptrdiff_t i = first; i < first + count; ++i) ratio_sum += pairs[static_cast<std::size_t>(i)].second;
  return desired * ratio_sum / static_cast<double>(count);
}

double ObservedStream::as_rate_per_s(double sum_over_platoons) const {
  return platoons_.empty() ? 0.0 : platoon_density_ * sum_over_platoons / static_cast<double>(platoons_.size());
}

void SortedSpeeds::add(double speed_mps) { sorted_mps_.push_back(speed_mps); }

void SortedSpeeds::finish() {
  std::sort(sorted_mps_.begin(), sorted_mps_.end());
  running_sum_mps_.clear();
  double sum = 0.0;
  for (double v : sorted_mps_) running_sum_mps_.push_back(sum += v);
}

SortedSpeeds::Sums SortedSpeeds::below(double u) const {
  const auto n = std::lower_bound(sorted_mps_.begin(), sorted_mps_.end(), u) - sorted_mps_.begin();
  return n == 0 ? Sums{} : Sums{static_cast<double>(n), running_sum_mps_[static_cast<std::size_t>(n - 1)]};
}

double SortedSpeeds::sum_mps() const { return all().speed; }

SortedSpeeds::Sums SortedSpeeds::all() const {
  return sorted_mps_.empty() ? Sums{} : Sums{static_cast<double>(sorted_mps_.size()), running_sum_mps_.back()};
}

double SortedSpeeds::sum_faster_by(double u) const {
  const Sums total = all();
  const Sums slow = below(u);
  return (total.speed - slow.speed) - u * (total.count - slow.count);
}

double SortedSpeeds::sum_slower_by(double u) const {
  const Sums slow = below(u);
  return u * slow.count - slow.speed;
}

double SortedSpeeds::sum_closing_with(double u) const {
  const Sums total = all();
  return total.speed + u * total.count;
}

double ObservedStream::mean_speed_mps() const {
  const auto n = static_cast<double>(vehicle_speeds_.size());
  return n == 0.0 ? 0.0 : vehicle_speeds_.sum_mps() / n;
}

template <typename Weight>
const Platoon& ObservedStream::draw(Random& rng, Weight w) const {
  double total = 0.0;
  for (const auto& p : platoons_) total += w(p.speed_mps);
  double target = rng.uniform() * total;
  for (const auto& p : platoons_) {
    target -= w(p.speed_mps);
    if (target < 0.0) return p;
  }
  return platoons_.back();
}

double ObservedStream::per_vehicle_rate_per_s(double sum_over_vehicles) const {
  const auto n = static_cast<double>(crossing_speeds_.size());
  return n == 0.0 ? 0.0 : crossing_density_ * sum_over_vehicles / n;
}

double ObservedStream::passing_share() const {
  const auto all = static_cast<double>(crossing_speeds_.size());
  return all == 0.0 ? 0.0 : 1.0 - static_cast<double>(vehicle_speeds_.size()) / all;
}

double ObservedStream::vehicles_rear_per_s(double u) const {
  return per_vehicle_rate_per_s(crossing_speeds_.sum_faster_by(u));
}

double ObservedStream::vehicles_front_per_s(double u) const {
  return per_vehicle_rate_per_s(crossing_speeds_.sum_slower_by(u));
}

double ObservedStream::vehicles_oncoming_per_s(double u) const {
  return per_vehicle_rate_per_s(crossing_speeds_.sum_closing_with(u));
}

double ObservedStream::rate_rear_per_s(double u) const {
  return as_rate_per_s(platoon_speeds_.sum_faster_by(u));
}

double ObservedStream::rate_front_per_s(double u) const {
  return as_rate_per_s(platoon_speeds_.sum_slower_by(u));
}

double ObservedStream::rate_oncoming_per_s(double u) const {
  return as_rate_per_s(platoon_speeds_.sum_closing_with(u));
}

const Platoon& ObservedStream::draw_rear(Random& rng, double u) const {
  return draw(rng, [u](double v) { return std::max(0.0, v - u); });
}

const Platoon& ObservedStream::draw_front(Random& rng, double u) const {
  return draw(rng, [u](double v) { return std::max(0.0, u - v); });
}

const Platoon& ObservedStream::draw_oncoming(Random& rng, double u) const {
  return draw(rng, [u](double v) { return v + u; });
}

std::vector<StreamVehicle> ObservedStream::stretch(Random& rng, double length_m, int candidates) const {
  std::vector<StreamVehicle> best;
  const double wanted = vehicle_density_ * length_m;
  for (int i = 0; i < std::max(1, candidates); ++i) {
    std::vector<StreamVehicle> s = one_stretch(rng, length_m);
    if (i == 0 || std::abs(static_cast<double>(s.size()) - wanted) < std::abs(static_cast<double>(best.size()) - wanted)) {
      best = std::move(s);
    }
  }
  return best;
}

std::vector<StreamVehicle> ObservedStream::one_stretch(Random& rng, double length_m) const {
  std::vector<StreamVehicle> out;
  if (snapshots_.empty()) return out;
  // Stretches longer than the observed road are put together from several snapshots.
  for (double done = 0.0; done < length_m;) {
    const auto index = static_cast<std::size_t>(rng.uniform() * static_cast<double>(snapshots_.size()));
    const auto& snap = snapshots_[std::min(index, snapshots_.size() - 1)];
    const double piece = std::min(length_m - done, sampled_length_m_);
    const double from = rng.uniform(0.0, sampled_length_m_ - piece);
    for (const auto& v : snap) {
      if (v.offset_m >= from && v.offset_m < from + piece) out.push_back({done + v.offset_m - from, v.vehicle});
    }
    done += piece;
  }
  return out;
}

std::size_t remove_overlapping(std::vector<StreamVehicle>& stretch) {
  // Front to back within each lane, each vehicle against the nearest one kept ahead of it.
  std::vector<std::size_t> order(stretch.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const StreamVehicle& x = stretch[a];
    const StreamVehicle& y = stretch[b];
    return x.vehicle.lane != y.vehicle.lane ? x.vehicle.lane < y.vehicle.lane : x.offset_m > y.offset_m;
  });
  std::vector<bool> removed(stretch.size(), false);
  const StreamVehicle* ahead = nullptr;
  for (std::size_t i : order) {
    const StreamVehicle& v = stretch[i];
    const bool same_lane = ahead != nullptr && ahead->vehicle.lane == v.vehicle.lane;
    if (same_lane && ahead->offset_m - v.offset_m < 0.5 * (ahead->vehicle.length_m + v.vehicle.length_m)) {
      removed[i] = true;
      continue;
    }
    ahead = &v;
  }
  std::vector<StreamVehicle> kept;
  kept.reserve(stretch.size());
  for (std::size_t i = 0; i < stretch.size(); ++i) {
    if (!removed[i]) kept.push_back(stretch[i]);
  }
  const std::size_t count = stretch.size() - kept.size();
  stretch = std::move(kept);
  return count;
}

}  // namespace entourage
