#include "recording/recording.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dds/topics.hpp"
#include "entourage_msg/ActorCommandPubSubTypes.h"
#include "entourage_msg/EgoStatePubSubTypes.h"
#include "entourage_msg/HandoffPubSubTypes.h"
#include "entourage_msg/PlayStatusPubSubTypes.h"
#include "entourage_msg/StepDonePubSubTypes.h"
#include "entourage_msg/VehicleStatePubSubTypes.h"
#include "entourage_msg/idl_text.hpp"
#include "recording/cdr.hpp"

namespace entourage::recording {

namespace {

constexpr const char* kProfile = "";  // no robotics profile: plain DDS/CDR
constexpr const char* kLibrary = "entourage";
constexpr const char* kMetadataName = "entourage.run";

// Channel (and schema) ids: fixed, so that files from equal runs are equal.
constexpr std::uint16_t kEgoChannel = 1;
constexpr std::uint16_t kVehicleChannel = 2;
constexpr std::uint16_t kHandoffChannel = 3;
constexpr std::uint16_t kPlayChannel = 4;
constexpr std::uint16_t kStepDoneChannel = 5;
constexpr std::uint16_t kCommandChannel = 6;

struct ChannelSpec {
  std::uint16_t id;
  dds::Topic topic;
};
constexpr ChannelSpec kChannels[] = {{kEgoChannel, dds::Topic::kEgoState},
                                     {kVehicleChannel, dds::Topic::kVehicleState},
                                     {kHandoffChannel, dds::Topic::kHandoff},
                                     {kPlayChannel, dds::Topic::kPlayStatus},
                                     {kStepDoneChannel, dds::Topic::kStepDone},
                                     {kCommandChannel, dds::Topic::kActorCommand}};

std::string fmt_double(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace

std::map<std::string, std::string> RecordingInfo::to_metadata() const {
  return {{"scenario_name", scenario_name}, {"scenario_file", scenario_file}, {"seed", std::to_string(seed)},
          {"mode", mode},                   {"step_s", fmt_double(step_s)},   {"peers", peers}};
}

RecordingInfo RecordingInfo::from_metadata(const std::map<std::string, std::string>& m) {
  RecordingInfo info;
  auto get = [&](const char* k) {
    auto it = m.find(k);
    return it == m.end() ? std::string() : it->second;
  };
  info.scenario_name = get("scenario_name");
  info.scenario_file = get("scenario_file");
  info.mode = get("mode");
  info.peers = get("peers");
  try {
    info.seed = std::stoull(get("seed"));
    info.step_s = std::stod(get("step_s"));
  } catch (...) {
  }
  return info;
}

bool RecordingWriter::open(const std::string& path, const RecordingInfo& info) {
  if (!writer_.open(path, kProfile, kLibrary)) return false;
  for (const auto& c : kChannels) {
    const auto& t = dds::info(c.topic);
    writer_.add_schema({c.id, std::string(t.type_name), "omgidl", std::string(msg::idl_text(t.idl_type))});
    writer_.add_channel({c.id, c.id, std::string(t.name), "cdr", {{"qos_profile", std::string(t.profile)}}});
  }
  writer_.add_attachment({0, 0, info.scenario_file, "text/plain", info.scenario_text});
  writer_.add_metadata({kMetadataName, info.to_metadata()});
  return true;
}

template <class PubSubT>
void RecordingWriter::write_sample(std::uint16_t channel, std::uint64_t log_time_ns,
                                   const typename PubSubT::type& sample) {
  mcap::Message m;
  m.channel_id = channel;
  m.sequence = ++sequence_[channel];
  m.log_time_ns = log_time_ns;
  m.publish_time_ns = log_time_ns;
  m.data = to_cdr<PubSubT>(sample);
  writer_.write(m);
}

void RecordingWriter::write_step(StepSamples s) {
  const auto t = static_cast<std::uint64_t>(std::llround(s.time_s * 1e9));
  std::sort(s.vehicles.begin(), s.vehicles.end(), [](const auto& a, const auto& b) {
    return a.owner() != b.owner() ? a.owner() < b.owner() : a.id() < b.id();
  });
  std::sort(s.handoffs.begin(), s.handoffs.end(), [](const auto& a, const auto& b) {
    if (a.from_service() != b.from_service()) return a.from_service() < b.from_service();
    if (a.vehicle_id() != b.vehicle_id()) return a.vehicle_id() < b.vehicle_id();
    return a.handoff_sequence() < b.handoff_sequence();
  });
  std::sort(s.plays.begin(), s.plays.end(), [](const auto& a, const auto& b) { return a.play_id() < b.play_id(); });
  // One writer (the director): commands for one vehicle keep the order it wrote them in.
  std::stable_sort(s.commands.begin(), s.commands.end(), [](const auto& a, const auto& b) {
    return a.vehicle_id() != b.vehicle_id() ? a.vehicle_id() < b.vehicle_id() : a.step() < b.step();
  });
  std::sort(s.done.begin(), s.done.end(), [](const auto& a, const auto& b) { return a.service() < b.service(); });
  if (s.ego) write_sample<msg::EgoStatePubSubType>(kEgoChannel, t, *s.ego);
  for (const auto& v : s.vehicles) write_sample<msg::VehicleStatePubSubType>(kVehicleChannel, t, v);
  for (const auto& h : s.handoffs) write_sample<msg::HandoffPubSubType>(kHandoffChannel, t, h);
  for (const auto& p : s.plays) write_sample<msg::PlayStatusPubSubType>(kPlayChannel, t, p);
  for (const auto& c : s.commands) write_sample<msg::ActorCommandPubSubType>(kCommandChannel, t, c);
  for (const auto& d : s.done) write_sample<msg::StepDonePubSubType>(kStepDoneChannel, t, d);
}

bool RecordingWriter::close() { return writer_.close(); }

std::optional<Recording> read_recording(const std::string& path, std::string* error) {
  auto contents = mcap::read_file(path, error);
  if (!contents) return std::nullopt;
  Recording r;
  for (const auto& md : contents->metadata) {
    if (md.name == kMetadataName) r.info = RecordingInfo::from_metadata(md.entries);
  }
  for (const auto& a : contents->attachments) {
    if (a.name == r.info.scenario_file || r.info.scenario_text.empty()) r.info.scenario_text = a.data;
  }
  std::map<std::uint16_t, dds::Topic> topic_of;
  for (const auto& [id, ch] : contents->channels) {
    for (const auto& t : dds::all_topics()) {
      if (ch.topic == t.name) topic_of[id] = t.topic;
    }
  }
  auto decode = [&r](auto decoded, auto& out) {
    if (decoded) {
      out.push_back(std::move(*decoded));
    } else {
      ++r.undecodable;
    }
  };
  for (const auto& m : contents->messages) {
    auto it = topic_of.find(m.channel_id);
    if (it == topic_of.end()) continue;
    switch (it->second) {
      case dds::Topic::kEgoState: decode(from_cdr<msg::EgoStatePubSubType>(m.data), r.egos); break;
      case dds::Topic::kVehicleState: decode(from_cdr<msg::VehicleStatePubSubType>(m.data), r.vehicles); break;
      case dds::Topic::kHandoff: decode(from_cdr<msg::HandoffPubSubType>(m.data), r.handoffs); break;
      case dds::Topic::kPlayStatus: decode(from_cdr<msg::PlayStatusPubSubType>(m.data), r.plays); break;
      case dds::Topic::kActorCommand:
        decode(from_cdr<msg::ActorCommandPubSubType>(m.data), r.commands);
        break;
      case dds::Topic::kStepDone: decode(from_cdr<msg::StepDonePubSubType>(m.data), r.done); break;
      case dds::Topic::kServiceStatus: break;
    }
  }
  return r;
}

}  // namespace entourage::recording
