#pragma once
// The DDS shell of a region service (micro, meso): subscribe, convert, call the core, publish.
// The core is anything with `StepOutput step(const StepInput&)`, `fleet()` and `counters()`.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include <spdlog/spdlog.h>

#include "entourage_msg/EgoStatePubSubTypes.h"
#include "entourage_msg/HandoffPubSubTypes.h"
#include "entourage_msg/ServiceStatusPubSubTypes.h"
#include "entourage_msg/StepDonePubSubTypes.h"
#include "entourage_msg/VehicleStatePubSubTypes.h"

#include "dds/convert.hpp"
#include "dds/inbox.hpp"
#include "dds/node.hpp"
#include "dds/runtime.hpp"
#include "dds/shell.hpp"
#include "road/road.hpp"
#include "traffic/carried_states.hpp"
#include "traffic/step_io.hpp"

namespace entourage::dds {

// Gathers the inputs of step k: the ego at k and k-1, every vehicle published for k-1 (by the
// others, from the inbox; by this service, from what it published), the handoffs received and the
// director's commands written at k-1 (with any that arrived too late for their own step).
inline StepInput gather_inputs(Step k, Inbox& inbox, const std::vector<ObservedVehicle>& own_prev) {
  StepInput in;
  in.step = k;
  in.ego = from_msg(*inbox.ego(k));
  if (k > 0) {
    if (auto e = inbox.ego(k - 1)) in.ego_prev = from_msg(*e);
    for (const auto& m : inbox.take_handoffs_upto(k - 1)) in.handoffs.push_back(from_msg(m));
    for (const auto& m : inbox.take_commands_upto(k - 1)) in.commands.push_back(from_msg(m));
    const Bucket b = inbox.take(k - 1);  // after the handoffs and commands, which it would take too
    in.world_prev.reserve(b.vehicles.size() + own_prev.size());
    for (const auto& m : b.vehicles) in.world_prev.push_back(from_msg(m));
  }
  in.world_prev.insert(in.world_prev.end(), own_prev.begin(), own_prev.end());
  // Arrival order over DDS is not deterministic; the order a core sees must be.
  std::sort(in.world_prev.begin(), in.world_prev.end(),
            [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.id < b.id; });
  // By vehicle, then step: a late command comes before a newer one for the same vehicle. Stable, so
  // that two commands of one step for one vehicle keep the order the director wrote them in.
  std::stable_sort(in.commands.begin(), in.commands.end(), [](const ActorCommand& a, const ActorCommand& b) {
    return a.vehicle != b.vehicle ? a.vehicle < b.vehicle : a.step < b.step;
  });
  return in;
}

// Publishes a step's vehicle states and handoffs; returns the counts and remembers the states
// as this service's part of the world for the next step. A state its peers would refuse (convert.hpp,
// `check`) is still published, and logged as an error here: refused, the vehicle would be missing
// from their world without a word at its source (a meso vehicle braking at 39 m/s² once became
// invisible to the generator, which placed the next vehicle on top of it).
//
// Given the step length (`carried_step_s`) it writes only the states a reader cannot carry forward
// from the last it got (traffic/carried_states.hpp), and tells its readers so in the step report
// (report_carrying).
class RegionPublisher {
 public:
  RegionPublisher(Node& node, ServiceId self, const Road& road, const SampleLimits& limits,
                  std::optional<double> carried_step_s = std::nullopt)
      : self_(self),
        road_(road),
        limits_(limits),
        states_(node.writer<msg::VehicleStatePubSubType>(Topic::kVehicleState)),
        handoffs_(node.writer<msg::HandoffPubSubType>(Topic::kHandoff)) {
    if (carried_step_s) sparse_.emplace(*carried_step_s);
  }

  TopicCounts publish(Step k, double time_s, const StepOutput& out) {
    TopicCounts written{};
    own_.clear();
    SparseStep sparse;
    if (sparse_) sparse = sparse_->select(out.states);
    auto to_write = sparse.states.begin();
    for (const VehicleReport& r : out.states) {
      const msg::VehicleState m = to_msg(r, self_, k, time_s, road_);
      own_.push_back(from_msg(m));
      if (sparse_) {  // only those a reader cannot carry forward (in id order, as out.states)
        if (to_write == sparse.states.end() || to_write->id != r.id) continue;
        ++to_write;
      }
      if (const auto why = check(m, limits_)) {
        ++unfit_states_;
        spdlog::error("published the state of vehicle {} at step {} that its peers refuse: {} [{} so far]", m.id(), k,
                      *why, unfit_states_);
      }
      states_.write(m);
      ++written[static_cast<std::size_t>(Topic::kVehicleState)];
    }
    // A vehicle handed on keeps its state instance in this writer: it is never unregistered. In
    // Fast DDS 2.9 a reader's acknowledgement that covers an unregister together with an older
    // sample of the same instance makes the writer also drop, unsent, the first sample that reader
    // has not acknowledged yet (StatefulWriter::check_acked_status walks the history with an
    // iterator that DataWriterHistory::remove_instance_changes shifts): a reader that lost that
    // sample gets a GAP instead and lockstep waits for it forever. No delay of the release avoids
    // that (acknowledgements lag arbitrarily behind delivery), and 2.9 has no safe per-instance
    // acknowledgement check, so the writer keeps a small record per vehicle this region ever owned.
    // tests/unit/lossy_handoff_test.cpp loses exactly that sample.
    for (const Handoff& h : out.handoffs) {
      handoffs_.write(to_msg(h, time_s, road_));
      ++written[static_cast<std::size_t>(Topic::kHandoff)];
    }
    gone_ = std::move(sparse.gone);
    return written;
  }

  // Completes the step report: whether the states are carried forward, and the vehicles gone.
  void report_carrying(msg::StepDone& report) const {
    report.carried_states(sparse_.has_value());
    if (sparse_) report.gone(gone_);
  }

  const std::vector<ObservedVehicle>& own() const { return own_; }
  // True once every matched reader has acknowledged every state published so far (false after
  // `timeout`).
  bool states_acknowledged(std::chrono::milliseconds timeout) const {
    return states_.wait_for_acknowledgments(timeout);
  }

 private:
  ServiceId self_;
  const Road& road_;
  SampleLimits limits_;
  std::uint64_t unfit_states_ = 0;
  Writer<msg::VehicleStatePubSubType> states_;
  Writer<msg::HandoffPubSubType> handoffs_;
  std::vector<ObservedVehicle> own_;
  std::optional<SparseStates> sparse_;  // with carried states
  std::vector<VehicleId> gone_;         // at the last step published
};

// `carried_states`: publish only the states a reader cannot carry forward (RegionPublisher).
template <class Core>
int run_region_service(const ServiceContext& ctx, Core& core, bool carried_states = false) {
  const ScenarioConfig& sc = ctx.scenario.config;
  const Road road(sc.road);
  Shell shell(ctx);
  RegionPublisher publisher(shell.node, ctx.id, road, SampleLimits::of(sc),
                            carried_states ? std::optional<double>(sc.step_s) : std::nullopt);
  if (!shell.discover(ctx)) return 1;
  run_step_loop(
      ctx, shell.inbox, shell.done, shell.status,
      [&](Step k) {
        const StepOutput out = core.step(gather_inputs(k, shell.inbox, publisher.own()));
        shell.status.set_counters(shell.inbox.bad_samples(), core.counters().duplicate_handoffs);
        return publisher.publish(k, static_cast<double>(k) * sc.step_s, out);
      },
      [&] { return static_cast<std::uint32_t>(core.fleet().size()); },
      [&](msg::StepDone& report) { publisher.report_carrying(report); });
  return 0;
}

}  // namespace entourage::dds
