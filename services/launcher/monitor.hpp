#pragma once
// The launcher's view of a run over DDS: the services' health reports, their step reports and
// the ego states, gathered from Fast DDS threads and read by the launcher's main loop. In real
// time it measures the delay from each ego state to the world state of the same step.

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

#include "entourage_msg/EgoState.h"
#include "entourage_msg/ServiceStatus.h"
#include "entourage_msg/StepDone.h"

#include "core/ids.hpp"
#include "dds/node.hpp"

namespace entourage::launcher {

struct Snapshot {
  std::map<std::uint16_t, msg::ServiceStatus> statuses;
  std::map<std::uint16_t, Step> last_step_done;
  std::map<std::uint16_t, std::uint32_t> owned;  // vehicles owned after the last reported step
  std::optional<Step> ego_step;
  double ego_speed_mps = 0.0;
};

class Monitor {
 public:
  // `world_producers`: the services whose step reports complete a step's world state.
  Monitor(dds::Node& node, std::vector<ServiceId> world_producers);

  Snapshot snapshot() const;
  // Delays (ms) from an ego state's arrival to the arrival of the last world producer's report of
  // the same step.
  std::vector<double> latencies_ms() const;

 private:
  void on_status(const msg::ServiceStatus& m);
  void on_done(const msg::StepDone& m);
  void on_ego(const msg::EgoState& m);

  mutable std::mutex mutex_;
  std::vector<ServiceId> producers_;
  Snapshot snap_;
  std::map<Step, std::chrono::steady_clock::time_point> ego_arrival_;
  std::map<Step, std::size_t> reports_;
  std::vector<double> latencies_ms_;
};

}  // namespace entourage::launcher
