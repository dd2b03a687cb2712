#pragma once
// Lockstep bookkeeping (no DDS, no threads): which services have reported a step done, how many
// samples each said it wrote on each topic, and how many of those have arrived. A step's inputs
// are complete when every peer has reported it and every announced sample is here; samples may
// arrive before or after the report, on different topics, in any order.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/ids.hpp"
#include "dds/topics.hpp"

namespace entourage::dds {

using TopicCounts = std::array<std::uint32_t, kTopicCount>;

// Topics whose samples a service waits for (bit per Topic).
using TopicMask = std::uint32_t;
constexpr TopicMask mask_of(Topic t) { return 1U << static_cast<unsigned>(t); }

class StepLedger {
 public:
  StepLedger(std::vector<ServiceId> peers, ServiceId self);

  void on_step_done(ServiceId from, Step step, const TopicCounts& announced);
  // True when this sample was the last `from` announced on `topic` for `step` (its report came
  // first): the only sample that can complete a step, so the only one worth waking a waiter for.
  bool on_sample(ServiceId from, Step step, Topic topic);

  // Every peer except self reported `step` and all their announced samples on `topics` arrived.
  bool complete(Step step, TopicMask topics) const;
  // Has `from` reported `step`?
  bool reported(ServiceId from, Step step) const;
  // Human-readable list of what is missing for `step` (for diagnostics and timeouts).
  std::string missing(Step step, TopicMask topics) const;
  // Drops bookkeeping of steps before `step`.
  void forget_before(Step step);

  const std::vector<ServiceId>& peers() const { return peers_; }

 private:
  struct Entry {
    bool reported = false;
    TopicCounts announced{};
    TopicCounts received{};
  };
  std::vector<ServiceId> peers_;
  ServiceId self_;
  std::map<Step, std::map<std::uint16_t, Entry>> steps_;
};

}  // namespace entourage::dds
