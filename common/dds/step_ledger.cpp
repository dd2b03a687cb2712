#include "dds/step_ledger.hpp"

#include <sstream>

namespace entourage::dds {

StepLedger::StepLedger(std::vector<ServiceId> peers, ServiceId self) : peers_(std::move(peers)), self_(self) {}

void StepLedger::on_step_done(ServiceId from, Step step, const TopicCounts& announced) {
  Entry& e = steps_[step][from.code()];
  e.reported = true;
  e.announced = announced;
}

bool StepLedger::on_sample(ServiceId from, Step step, Topic topic) {
  Entry& e = steps_[step][from.code()];
  const auto t = static_cast<std::size_t>(topic);
  ++e.received[t];
  return e.reported && e.received[t] == e.announced[t];
}

bool StepLedger::reported(ServiceId from, Step step) const {
  auto s = steps_.find(step);
  if (s == steps_.end()) return false;
  auto e = s->second.find(from.code());
  return e != s->second.end() && e->second.reported;
}

bool StepLedger::complete(Step step, TopicMask topics) const {
  auto s = steps_.find(step);
  for (const ServiceId& p : peers_) {
    if (p == self_) continue;
    if (s == steps_.end()) return false;
    auto e = s->second.find(p.code());
    if (e == s->second.end() || !e->second.reported) return false;
    for (std::size_t t = 0; t < kTopicCount; ++t) {
      if ((topics & (1U << t)) != 0 && e->second.received[t] < e->second.announced[t]) return false;
    }
  }
  return true;
}

std::string StepLedger::missing(Step step, TopicMask topics) const {
  std::ostringstream os;
  auto s = steps_.find(step);
  for (const ServiceId& p : peers_) {
    if (p == self_) continue;
    const Entry* e = nullptr;
    if (s != steps_.end()) {
      auto it = s->second.find(p.code());
      if (it != s->second.end()) e = &it->second;
    }
    if (e == nullptr || !e->reported) {
      os << ' ' << to_string(p) << " (no step report)";
      continue;
    }
    for (std::size_t t = 0; t < kTopicCount; ++t) {
      if ((topics & (1U << t)) != 0 && e->received[t] < e->announced[t]) {
        os << ' ' << to_string(p) << " (" << e->received[t] << '/' << e->announced[t] << ' '
           << info(static_cast<Topic>(t)).name << ')';
      }
    }
  }
  return os.str();
}

void StepLedger::forget_before(Step step) { steps_.erase(steps_.begin(), steps_.lower_bound(step)); }

}  // namespace entourage::dds
