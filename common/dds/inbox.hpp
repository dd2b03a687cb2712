#pragma once
// Where a service shell collects what arrives over DDS, by step, until its main thread takes it.
// Reader callbacks (Fast DDS threads) add samples; the main thread waits for a step's inputs to
// be complete (lockstep) or for the next ego state (real time) and takes them.
//
// Every sample is checked on arrival (convert.hpp); a bad one is logged, counted and dropped, and
// the service carries on. Samples a service published itself are ignored: it knows them already.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

#include "entourage_msg/ServiceStatus.h"
#include "dds/convert.hpp"
#include "dds/step_ledger.hpp"
#include "road/road.hpp"
#include "traffic/carried_states.hpp"

namespace entourage::dds {

struct Bucket {
  std::vector<msg::VehicleState> vehicles;
  std::vector<msg::Handoff> handoffs;
  std::vector<msg::PlayStatus> plays;
  std::vector<msg::ActorCommand> commands;
  std::vector<msg::StepDone> done;
};

class Inbox {
 public:
  // keep_refused: refused samples are still counted and logged, but kept as well (the recorder
  // records what was on the wire, bad samples included).
  Inbox(std::vector<ServiceId> peers, ServiceId self, SampleLimits limits, bool keep_refused = false);

  // Reader callbacks.
  void add(const msg::EgoState& m);
  void add(const msg::VehicleState& m);
  void add(const msg::Handoff& m);
  void add(const msg::PlayStatus& m);
  void add(const msg::ActorCommand& m);
  void add(const msg::StepDone& m);
  void add(const msg::ServiceStatus& m);

  // Waits until `ready()` (evaluated under the lock) is true or the timeout passes.
  template <class Pred>
  bool wait(Pred ready, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, timeout, [&] { return ready(*this); });
  }

  // The queries below take the lock; inside wait()'s predicate use the *_locked variants.
  bool has_ego(Step step) const;
  std::optional<msg::EgoState> ego(Step step) const;
  std::optional<Step> newest_ego_step() const;
  bool complete(Step step, TopicMask topics) const;
  std::string missing(Step step, TopicMask topics) const;
  std::map<std::uint16_t, msg::ServiceStatus> statuses() const;
  std::uint64_t bad_samples() const;

  bool has_ego_locked(Step step) const { return egos_.count(step) != 0; }
  bool complete_locked(Step step, TopicMask topics) const { return ledger_.complete(step, topics); }
  std::optional<Step> newest_ego_step_locked() const;
  const std::map<std::uint16_t, msg::ServiceStatus>& statuses_locked() const { return statuses_; }

  // States a publisher carries forward (its step report's `carried_states`): the inbox rebuilds them
  // in `take` (traffic/carried_states.hpp), on this road at this step length, as the publisher
  // would have published them. Without it such a publisher's carried vehicles are missing.
  void carry_states(const RoadConfig& road, double step_s);
  // Removes and returns what arrived for `step`; with carry_states, a publisher's carried vehicles
  // rebuilt in it. Taken step after step (lockstep): the rebuilding follows a publisher's steps.
  Bucket take(Step step);
  // Removes and returns every handoff of steps up to and including `step`.
  std::vector<msg::Handoff> take_handoffs_upto(Step step);
  // Removes and returns every director command of steps up to and including `step`.
  std::vector<msg::ActorCommand> take_commands_upto(Step step);
  // Steps before `step` that still hold samples (late arrivals after their step was taken).
  std::vector<Step> steps_with_samples_before(Step step) const;
  // Drops everything (samples, ego states, bookkeeping) of steps before `step`; handoffs and director
  // commands are kept (moved to `step`, their messages unchanged) and taken with the next ones.
  void forget_before(Step step);
  // Drops ego states and bookkeeping of steps before `step` but keeps their samples.
  void forget_bookkeeping_before(Step step);

 private:
  bool refuse(const std::optional<std::string>& reason, const char* what, std::uint32_t id, Step step);
  // Counts a sample of a lockstep topic as arrived (refused or not) and wakes the waiting step
  // only where it is the last its sender announced (StepLedger::on_sample): a wake per sample cost
  // every service a thread switch per vehicle state. Under the lock.
  void arrived_locked(ServiceId from, Step step, Topic topic);
  // Removes and returns the samples of kind `samples` of every step before `end` (lock held).
  template <class T>
  std::vector<T> take_before_locked(Step end, std::vector<T> Bucket::*samples);
  // Replaces, in `b`, the vehicles of each publisher that carries its states forward by all of its
  // states at `step` (lock held).
  void carry_forward_locked(Step step, Bucket& b);

  struct Carrying {  // the road and step length states are rebuilt on (carry_states)
    Road road;
    double step_s;
  };
  struct Carried {
    explicit Carried(double step_s) : tracks(step_s) {}
    StateTracks tracks;
    std::optional<Step> last;  // the step last rebuilt
  };

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  ServiceId self_;
  SampleLimits limits_;
  bool keep_refused_;
  StepLedger ledger_;
  std::map<Step, msg::EgoState> egos_;
  std::map<Step, Bucket> buckets_;
  std::map<std::uint16_t, msg::ServiceStatus> statuses_;
  std::uint64_t bad_samples_ = 0;
  std::optional<Carrying> carrying_;          // with carry_states
  std::map<std::uint16_t, Carried> carried_;  // by publisher
  std::uint64_t carrying_gaps_ = 0;           // steps of such a publisher taken out of order (logged)
};

}  // namespace entourage::dds
