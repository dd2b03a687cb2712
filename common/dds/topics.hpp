#pragma once
// The topics of Entourage, their IDL types and QoS profiles (idl/entourage_qos.xml), and which
// roles write and read each (the process table of ../DESIGN.md).

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/ids.hpp"

namespace entourage::dds {

enum class Topic : std::uint8_t {
  kEgoState = 0,
  kVehicleState = 1,
  kHandoff = 2,
  kStepDone = 3,
  kServiceStatus = 4,
  kPlayStatus = 5,
  kActorCommand = 6,
};
inline constexpr std::size_t kTopicCount = 7;

struct TopicInfo {
  Topic topic;
  std::string_view name;       // DDS topic name
  std::string_view idl_type;   // idl/<idl_type>.idl
  std::string_view type_name;  // fully qualified type name
  std::string_view profile;    // QoS profile prefix: <profile>_writer / <profile>_reader
  bool recorded;               // part of reproducible recordings
};

const TopicInfo& info(Topic t);
const std::array<TopicInfo, kTopicCount>& all_topics();

// Does a service of `role` write / read topic `t`?
bool writes(Role role, Topic t);
bool reads(Role role, Topic t);

// How many of `peers` other than `self` write / read `t`: the matches a service waits for
// before it reports ready.
int expected_writers(Topic t, const std::vector<ServiceId>& peers, ServiceId self);
int expected_readers(Topic t, const std::vector<ServiceId>& peers, ServiceId self);

}  // namespace entourage::dds
