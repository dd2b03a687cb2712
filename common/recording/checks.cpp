#include "recording/checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

namespace entourage::recording {

namespace {

constexpr std::size_t kExamples = 5;           // violations quoted in a detail
constexpr double kTouchTolerance_m = 1e-6;     // boxes that only touch do not overlap

struct Range {
  std::uint64_t first = 0;
  std::uint64_t last = 0;
  std::uint64_t count = 0;
  std::string first_region;
  std::string last_region;
};

class Violations {
 public:
  void add(const std::string& what) {
    if (++count_ <= kExamples) os_ << (count_ > 1 ? "; " : "") << what;
  }
  CheckResult result(const std::string& name, const std::string& ok_detail) const {
    return {name, count_ == 0, count_, count_ == 0 ? ok_detail : os_.str()};
  }

 private:
  std::uint64_t count_ = 0;
  std::ostringstream os_;
};

// Rows of one step, in order.
template <typename F>
void for_each_step(const Tables& t, F f) {
  std::size_t i = 0;
  std::size_t e = 0;
  while (i < t.vehicles.size() || e < t.ego.size()) {
    std::uint64_t step = ~0ULL;
    if (i < t.vehicles.size()) step = t.vehicles[i].step;
    if (e < t.ego.size()) step = std::min(step, t.ego[e].step);
    std::size_t j = i;
    while (j < t.vehicles.size() && t.vehicles[j].step == step) ++j;
    const EgoRow* ego = (e < t.ego.size() && t.ego[e].step == step) ? &t.ego[e] : nullptr;
    f(step, i, j, ego);
    i = j;
    if (ego != nullptr) ++e;
  }
}

CheckResult check_one_owner(const Tables& t) {
  Violations v;
  for (std::size_t i = 1; i < t.vehicles.size(); ++i) {
    const auto& a = t.vehicles[i - 1];
    const auto& b = t.vehicles[i];
    if (a.step == b.step && a.id == b.id) {
      v.add("vehicle " + std::to_string(a.id) + " at step " + std::to_string(a.step) + " by " + a.owner + " and " +
            b.owner);
    }
  }
  return v.result("one_owner", "every vehicle has one owner in every step");
}

std::map<std::uint32_t, Range> ranges_of(const Tables& t) {
  std::map<std::uint32_t, Range> r;
  for (const auto& row : t.vehicles) {
    auto [it, fresh] = r.try_emplace(row.id);
    Range& x = it->second;
    if (fresh) {
      x.first = row.step;
      x.first_region = row.region;
    }
    x.last = row.step;
    x.last_region = row.region;
    ++x.count;
  }
  return r;
}

CheckResult check_continuity(const std::map<std::uint32_t, Range>& ranges) {
  Violations v;
  for (const auto& [id, r] : ranges) {
    if (r.count != r.last - r.first + 1) {
      v.add("vehicle " + std::to_string(id) + " missing in " + std::to_string(r.last - r.first + 1 - r.count) +
            " steps between " + std::to_string(r.first) + " and " + std::to_string(r.last));
    }
  }
  return v.result("continuity", "every vehicle is present in every step of its life");
}

CheckResult check_no_pop_in(const Tables& t, const std::map<std::uint32_t, Range>& ranges) {
  if (t.vehicles.empty()) return {"no_pop_in", false, 1, "no vehicles recorded"};
  // The initial fill shows in the first two steps with vehicles: what the generator keeps ahead of
  // the window at once, the rest once micro and meso have taken it over.
  const std::uint64_t fill_step = t.vehicles.front().step + 1;
  // The world ends before the last step every region published: an external simulator may go on
  // publishing ego states after the run, and in real time the services stop a step or two apart
  // (a vehicle of one that stopped first is not gone, its owner is). An owner's last step itself
  // may be cut short: the recorder stops while its samples are on the way. Its earlier steps are
  // whole, as one writer's samples arrive in order.
  std::map<std::string, std::uint64_t> last_by_owner;
  for (const auto& row : t.vehicles) {
    auto& last = last_by_owner[row.owner];
    last = std::max(last, row.step);
  }
  std::uint64_t last_step = t.vehicles.back().step;
  for (const auto& [owner, last] : last_by_owner) last_step = std::min(last_step, last);
  const std::uint64_t last_whole_step = last_step > fill_step ? last_step - 1 : last_step;
  Violations v;
  std::uint64_t appeared = 0;
  std::uint64_t vanished = 0;
  for (const auto& [id, r] : ranges) {
    if (r.first > fill_step) {
      ++appeared;
      if (r.first_region == "inner") v.add("vehicle " + std::to_string(id) + " appears in the inner region at step " + std::to_string(r.first));
    }
    if (r.last < last_whole_step) {
      ++vanished;
      if (r.last_region == "inner") v.add("vehicle " + std::to_string(id) + " disappears in the inner region after step " + std::to_string(r.last));
    }
  }
  return v.result("no_pop_in", std::to_string(appeared) + " vehicles appeared and " + std::to_string(vanished) +
                                   " disappeared, all outside the inner region");
}

struct Box {
  std::uint32_t id;
  int direction;
  double s, d, half_length, half_width;
};

CheckResult check_no_overlap(const Tables& t, const EgoConfig& ego_config) {
  Violations v;
  std::vector<Box> boxes;
  for_each_step(t, [&](std::uint64_t step, std::size_t i, std::size_t j, const EgoRow* ego) {
    boxes.clear();
    for (std::size_t k = i; k < j; ++k) {
      const auto& r = t.vehicles[k];
      boxes.push_back({r.id, r.direction, r.s_m, r.d_m, r.length_m / 2, r.width_m / 2});
    }
    if (ego != nullptr && !ego_config.transparent) {
      boxes.push_back({0, 1, ego->s_m, ego->d_m, ego_config.length_m / 2, ego_config.width_m / 2});
    }
    std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.s < b.s; });
    for (std::size_t a = 0; a < boxes.size(); ++a) {
      for (std::size_t b = a + 1; b < boxes.size(); ++b) {
        const double ds = boxes[b].s - boxes[a].s;
        if (ds >= boxes[a].half_length + boxes[b].half_length + 15.0) break;  // no longer vehicle than 30 m
        // Both directions: on a two-lane road an overtaker in the oncoming lane meets oncoming
        // traffic at the same d (a head-on collision is an overlap too).
        const bool long_overlap = ds < boxes[a].half_length + boxes[b].half_length - kTouchTolerance_m;
        const bool lat_overlap =
            std::abs(boxes[a].d - boxes[b].d) < boxes[a].half_width + boxes[b].half_width - kTouchTolerance_m;
        if (long_overlap && lat_overlap) {
          v.add("vehicles " + std::to_string(boxes[a].id) + " and " + std::to_string(boxes[b].id) + " overlap at step " +
                std::to_string(step));
        }
      }
    }
  });
  return v.result("no_overlap", "no two vehicles overlap (either direction)");
}

CheckResult check_ego_interacts(const Tables& t, bool transparent) {
  if (transparent) return {"ego_interacts", true, 0, "the ego is transparent: the traffic does not see it"};
  std::uint64_t ego_leads = 0;
  std::uint64_t ego_follows = 0;
  std::uint64_t followed_inside = 0;  // steps with a vehicle right behind the ego in the inner region
  for_each_step(t, [&](std::uint64_t, std::size_t i, std::size_t j, const EgoRow* ego) {
    if (ego == nullptr) return;
    const VehicleRow* leader = nullptr;
    const VehicleRow* follower = nullptr;
    for (std::size_t k = i; k < j; ++k) {
      const auto& r = t.vehicles[k];
      if (r.direction != 1 || r.lane != ego->lane) continue;
      if (r.s_m > ego->s_m && (leader == nullptr || r.s_m < leader->s_m)) leader = &r;
      if (r.s_m < ego->s_m && (follower == nullptr || r.s_m > follower->s_m)) follower = &r;
    }
    if (follower != nullptr && follower->owner == "micro") ++ego_leads;
    if (follower != nullptr && follower->region == "inner") ++followed_inside;
    if (leader != nullptr && leader->owner == "micro") ++ego_follows;
  });
  // Nobody behind the ego in the inner region for a whole drive (a short rural drive at the ego's
  // pace may have no one catch up): nothing to check.
  CheckResult r{"ego_interacts", ego_leads > 0 || followed_inside == 0, 0, ""};
  r.detail = "the ego leads a micro vehicle in " + std::to_string(ego_leads) + " steps and follows one in " +
             std::to_string(ego_follows) + " steps";
  if (followed_inside == 0) r.detail += " (no vehicle drove behind it in the inner region)";
  r.violations = r.passed ? 0 : 1;
  return r;
}

}  // namespace

std::vector<CheckResult> check_invariants(const Tables& t, const EgoConfig& ego) {
  const auto ranges = ranges_of(t);
  return {check_one_owner(t), check_continuity(ranges), check_no_pop_in(t, ranges), check_no_overlap(t, ego),
          check_ego_interacts(t, ego.transparent)};
}

}  // namespace entourage::recording
