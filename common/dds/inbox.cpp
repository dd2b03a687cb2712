#include "dds/inbox.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

namespace entourage::dds {

namespace {
constexpr ServiceId kEgoService{Role::kEgo, 0};
// The first few refused samples are logged one by one, then one in this many.
constexpr std::uint64_t kLogEveryNthBadSample = 100;
constexpr std::uint64_t kLogFirstBadSamples = 10;
}  // namespace

Inbox::Inbox(std::vector<ServiceId> peers, ServiceId self, SampleLimits limits, bool keep_refused)
    : self_(self), limits_(limits), keep_refused_(keep_refused), ledger_(std::move(peers), self) {}

bool Inbox::refuse(const std::optional<std::string>& reason, const char* what, std::uint32_t id, Step step) {
  if (!reason) return false;
  ++bad_samples_;
  if (bad_samples_ <= kLogFirstBadSamples || bad_samples_ % kLogEveryNthBadSample == 0) {
    spdlog::warn("{} {} sample (id {}, step {}): {} [{} bad so far]", keep_refused_ ? "bad (kept)" : "refused", what,
                 id, step, *reason, bad_samples_);
  }
  return !keep_refused_;
}

void Inbox::arrived_locked(ServiceId from, Step step, Topic topic) {
  if (ledger_.on_sample(from, step, topic)) changed_.notify_all();
}

void Inbox::add(const msg::EgoState& m) {
  if (self_ == kEgoService) return;
  std::lock_guard<std::mutex> lock(mutex_);
  ledger_.on_sample(kEgoService, m.step(), Topic::kEgoState);  // arrived, even if refused
  if (!refuse(check(m, limits_), "ego_state", m.ego_id(), m.step())) egos_[m.step()] = m;
  changed_.notify_all();
}

void Inbox::add(const msg::VehicleState& m) {
  const ServiceId from = ServiceId::from_code(m.owner());
  if (from == self_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  arrived_locked(from, m.step(), Topic::kVehicleState);
  if (!refuse(check(m, limits_), "vehicle_state", m.id(), m.step())) buckets_[m.step()].vehicles.push_back(m);
}

void Inbox::add(const msg::Handoff& m) {
  const ServiceId from = ServiceId::from_code(m.from_service());
  if (from == self_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  arrived_locked(from, m.step(), Topic::kHandoff);
  if (!refuse(check(m, limits_), "handoff", m.vehicle_id(), m.step())) buckets_[m.step()].handoffs.push_back(m);
}

void Inbox::add(const msg::PlayStatus& m) {
  const ServiceId from{Role::kDirector, 0};
  if (from == self_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  arrived_locked(from, m.step(), Topic::kPlayStatus);  // arrived, even if refused
  if (!refuse(check(m, limits_), "play_status", m.play_id(), m.step())) buckets_[m.step()].plays.push_back(m);
}

void Inbox::add(const msg::ActorCommand& m) {
  const ServiceId from{Role::kDirector, 0};
  if (from == self_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  arrived_locked(from, m.step(), Topic::kActorCommand);
  if (!refuse(check(m, limits_), "actor_command", m.vehicle_id(), m.step())) buckets_[m.step()].commands.push_back(m);
}

void Inbox::add(const msg::StepDone& m) {
  const ServiceId from = ServiceId::from_code(m.service());
  if (from == self_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  buckets_[m.step()].done.push_back(m);
  ledger_.on_step_done(from, m.step(), counts_of(m));
  changed_.notify_all();
}

void Inbox::add(const msg::ServiceStatus& m) {
  std::lock_guard<std::mutex> lock(mutex_);
  statuses_[m.service()] = m;
  changed_.notify_all();
}

bool Inbox::has_ego(Step step) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return has_ego_locked(step);
}

std::optional<msg::EgoState> Inbox::ego(Step step) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = egos_.find(step);
  if (it == egos_.end()) return std::nullopt;
  return it->second;
}

std::optional<Step> Inbox::newest_ego_step_locked() const {
  if (egos_.empty()) return std::nullopt;
  return egos_.rbegin()->first;
}

std::optional<Step> Inbox::newest_ego_step() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return newest_ego_step_locked();
}

bool Inbox::complete(Step step, TopicMask topics) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return ledger_.complete(step, topics);
}

std::string Inbox::missing(Step step, TopicMask topics) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return ledger_.missing(step, topics);
}

std::map<std::uint16_t, msg::ServiceStatus> Inbox::statuses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return statuses_;
}

std::uint64_t Inbox::bad_samples() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return bad_samples_;
}

void Inbox::carry_states(const RoadConfig& road, double step_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  carrying_.emplace(Carrying{Road(road), step_s});
}

Bucket Inbox::take(Step step) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = buckets_.find(step);
  if (it == buckets_.end()) return {};
  Bucket b = std::move(it->second);
  buckets_.erase(it);
  carry_forward_locked(step, b);
  return b;
}

void Inbox::carry_forward_locked(Step step, Bucket& b) {
  for (const msg::StepDone& d : b.done) {
    if (!d.carried_states()) continue;
    if (!carrying_) {  // a shell always sets it (Shell)
      spdlog::error("{} carries its vehicle states forward and this inbox cannot rebuild them: they are missing",
                    to_string(ServiceId::from_code(d.service())));
      continue;
    }
    Carried& c = carried_.try_emplace(d.service(), carrying_->step_s).first->second;
    if (c.last && step != *c.last + 1) {
      ++carrying_gaps_;
      spdlog::error("step {} of {} taken after step {}: its carried vehicle states are off until it publishes them "
                    "again [{} gaps so far]",
                    step, to_string(ServiceId::from_code(d.service())), *c.last, carrying_gaps_);
    }
    c.last = step;
    const auto theirs = [&d](const msg::VehicleState& m) { return m.owner() == d.service(); };
    std::vector<VehicleReport> published;
    for (const msg::VehicleState& m : b.vehicles) {
      if (theirs(m)) published.push_back(report_from_msg(m));
    }
    b.vehicles.erase(std::remove_if(b.vehicles.begin(), b.vehicles.end(), theirs), b.vehicles.end());
    std::sort(published.begin(), published.end(),
              [](const VehicleReport& x, const VehicleReport& y) { return x.id < y.id; });
    const ServiceId from = ServiceId::from_code(d.service());
    const double time_s = static_cast<double>(step) * carrying_->step_s;  // as the publisher stamps its states
    for (const VehicleReport& r : c.tracks.step(published, d.gone())) {
      b.vehicles.push_back(to_msg(r, from, step, time_s, carrying_->road));
    }
  }
}

template <class T>
std::vector<T> Inbox::take_before_locked(Step end, std::vector<T> Bucket::*samples) {
  std::vector<T> out;
  for (auto it = buckets_.begin(); it != buckets_.end() && it->first < end; ++it) {
    auto& v = it->second.*samples;
    out.insert(out.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
    v.clear();
  }
  return out;
}

std::vector<msg::Handoff> Inbox::take_handoffs_upto(Step step) {
  std::lock_guard<std::mutex> lock(mutex_);
  return take_before_locked(step + 1, &Bucket::handoffs);
}

std::vector<msg::ActorCommand> Inbox::take_commands_upto(Step step) {
  std::lock_guard<std::mutex> lock(mutex_);
  return take_before_locked(step + 1, &Bucket::commands);
}

void Inbox::forget_bookkeeping_before(Step step) {
  std::lock_guard<std::mutex> lock(mutex_);
  egos_.erase(egos_.begin(), egos_.lower_bound(step));
  ledger_.forget_before(step);
}

std::vector<Step> Inbox::steps_with_samples_before(Step step) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Step> out;
  for (auto it = buckets_.begin(); it != buckets_.end() && it->first < step; ++it) {
    const Bucket& b = it->second;
    if (!b.vehicles.empty() || !b.handoffs.empty() || !b.plays.empty() || !b.commands.empty() || !b.done.empty()) {
      out.push_back(it->first);
    }
  }
  return out;
}

void Inbox::forget_before(Step step) {
  std::lock_guard<std::mutex> lock(mutex_);
  // Handoffs and director commands are never dropped: a late one is still applied (at the next step).
  std::vector<msg::Handoff> handoffs = take_before_locked(step, &Bucket::handoffs);
  std::vector<msg::ActorCommand> commands = take_before_locked(step, &Bucket::commands);
  buckets_.erase(buckets_.begin(), buckets_.lower_bound(step));
  auto keep = [this, step](auto& kept, auto Bucket::*samples) {
    if (kept.empty()) return;
    auto& dst = buckets_[step].*samples;
    dst.insert(dst.end(), std::make_move_iterator(kept.begin()), std::make_move_iterator(kept.end()));
  };
  keep(handoffs, &Bucket::handoffs);
  keep(commands, &Bucket::commands);
  egos_.erase(egos_.begin(), egos_.lower_bound(step));
  ledger_.forget_before(step);
}

}  // namespace entourage::dds
