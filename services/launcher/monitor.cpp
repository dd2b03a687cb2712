#include "launcher/monitor.hpp"

#include <algorithm>

#include "entourage_msg/EgoStatePubSubTypes.h"
#include "entourage_msg/ServiceStatusPubSubTypes.h"
#include "entourage_msg/StepDonePubSubTypes.h"

namespace entourage::launcher {

namespace {
// Ego arrivals older than this many steps without a complete world are forgotten.
constexpr Step kLatencyHorizonSteps = 200;
}  // namespace

Monitor::Monitor(dds::Node& node, std::vector<ServiceId> world_producers) : producers_(std::move(world_producers)) {
  node.reader<msg::ServiceStatusPubSubType>(dds::Topic::kServiceStatus,
                                            [this](const msg::ServiceStatus& m) { on_status(m); });
  node.reader<msg::StepDonePubSubType>(dds::Topic::kStepDone, [this](const msg::StepDone& m) { on_done(m); });
  node.reader<msg::EgoStatePubSubType>(dds::Topic::kEgoState, [this](const msg::EgoState& m) { on_ego(m); });
}

void Monitor::on_status(const msg::ServiceStatus& m) {
  std::lock_guard<std::mutex> lock(mutex_);
  snap_.statuses[m.service()] = m;
}

void Monitor::on_done(const msg::StepDone& m) {
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  auto& last = snap_.last_step_done[m.service()];
  last = std::max<Step>(last, m.step());
  snap_.owned[m.service()] = m.owned_vehicles();
  const ServiceId from = ServiceId::from_code(m.service());
  if (std::find(producers_.begin(), producers_.end(), from) == producers_.end()) return;
  if (++reports_[m.step()] < producers_.size()) return;
  reports_.erase(m.step());
  auto it = ego_arrival_.find(m.step());
  if (it != ego_arrival_.end()) {
    latencies_ms_.push_back(std::chrono::duration<double, std::milli>(now - it->second).count());
    ego_arrival_.erase(ego_arrival_.begin(), std::next(it));
  }
}

void Monitor::on_ego(const msg::EgoState& m) {
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(mutex_);
  snap_.ego_step = m.step();
  snap_.ego_speed_mps = m.speed_mps();
  ego_arrival_[m.step()] = now;
  if (m.step() > kLatencyHorizonSteps) {
    const Step horizon = m.step() - kLatencyHorizonSteps;
    ego_arrival_.erase(ego_arrival_.begin(), ego_arrival_.lower_bound(horizon));
    reports_.erase(reports_.begin(), reports_.lower_bound(horizon));
  }
}

Snapshot Monitor::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return snap_;
}

std::vector<double> Monitor::latencies_ms() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return latencies_ms_;
}

}  // namespace entourage::launcher
