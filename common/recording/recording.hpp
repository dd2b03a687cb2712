#pragma once
// Recordings: MCAP files with one channel per recorded topic. Each message is a DDS sample as
// its CDR bytes (message encoding "cdr"), its channel's schema the topic type's IDL text (schema
// encoding "omgidl"), log time the simulated time of its step. The scenario file is attached and
// the run's settings are a metadata record. In lockstep, samples of a step are written in a
// fixed order (topic, then source service, then key), so equal runs give byte-identical files.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "entourage_msg/ActorCommand.h"
#include "entourage_msg/EgoState.h"
#include "entourage_msg/Handoff.h"
#include "entourage_msg/PlayStatus.h"
#include "entourage_msg/StepDone.h"
#include "entourage_msg/VehicleState.h"

#include "mcap/mcap.hpp"

namespace entourage::recording {

struct RecordingInfo {
  std::string scenario_name;
  std::string scenario_file;  // as given to the launcher
  std::string scenario_text;
  std::uint64_t seed = 0;
  std::string mode;  // lockstep or realtime
  double step_s = 0.1;
  std::string peers;

  std::map<std::string, std::string> to_metadata() const;
  static RecordingInfo from_metadata(const std::map<std::string, std::string>& m);
};

// Everything recorded for one step.
struct StepSamples {
  std::uint64_t step = 0;
  double time_s = 0.0;
  std::optional<msg::EgoState> ego;
  std::vector<msg::VehicleState> vehicles;
  std::vector<msg::Handoff> handoffs;
  std::vector<msg::PlayStatus> plays;
  std::vector<msg::ActorCommand> commands;
  std::vector<msg::StepDone> done;
};

class RecordingWriter {
 public:
  // Creates the file; false (with error()) if it cannot.
  bool open(const std::string& path, const RecordingInfo& info);
  // Writes one step's samples, sorted into the fixed order.
  void write_step(StepSamples samples);
  bool close();
  const std::string& error() const { return writer_.error(); }
  std::uint64_t messages() const { return writer_.message_count(); }

 private:
  template <class PubSubT>
  void write_sample(std::uint16_t channel, std::uint64_t log_time_ns, const typename PubSubT::type& sample);

  mcap::Writer writer_;
  std::map<std::uint16_t, std::uint32_t> sequence_;
};

// A recording read back whole.
struct Recording {
  RecordingInfo info;
  std::vector<msg::EgoState> egos;
  std::vector<msg::VehicleState> vehicles;
  std::vector<msg::Handoff> handoffs;
  std::vector<msg::PlayStatus> plays;
  std::vector<msg::ActorCommand> commands;
  std::vector<msg::StepDone> done;
  std::uint64_t undecodable = 0;  // messages whose bytes did not decode (reported, not fatal)
};

std::optional<Recording> read_recording(const std::string& path, std::string* error);

}  // namespace entourage::recording
