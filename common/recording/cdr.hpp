#pragma once
// A topic sample as the bytes its type serializes to (CDR with its 4-byte encapsulation header),
// exactly what travels over RTPS: what recordings store, so that a replay is lossless.

#include <cstdint>
#include <optional>
#include <vector>

#include <fastdds/rtps/common/SerializedPayload.h>

namespace entourage::recording {

template <class PubSubT>
std::vector<std::uint8_t> to_cdr(const typename PubSubT::type& sample) {
  PubSubT type;
  auto* data = const_cast<typename PubSubT::type*>(&sample);
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(data)());
  type.serialize(data, &payload);
  return std::vector<std::uint8_t>(payload.data, payload.data + payload.length);
}

template <class PubSubT>
std::optional<typename PubSubT::type> from_cdr(const std::vector<std::uint8_t>& bytes) {
  PubSubT type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  typename PubSubT::type sample;
  try {
    if (!type.deserialize(&payload, &sample)) return std::nullopt;
  } catch (...) {
    return std::nullopt;
  }
  return sample;
}

}  // namespace entourage::recording
