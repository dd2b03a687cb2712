#pragma once
// A service's presence on the DDS bus: one participant per process, created from the QoS
// profile file, with typed writers and readers for Entourage's topics. Reader callbacks run on
// Fast DDS's threads; a shell hands the samples to its main thread (see inbox.hpp).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include "dds/topics.hpp"

namespace entourage::dds {

namespace fdds = eprosima::fastdds::dds;

class DdsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <class PubSubT>
class Writer {
 public:
  using Sample = typename PubSubT::type;
  Writer() = default;
  explicit Writer(fdds::DataWriter* w) : writer_(w) {}

  // Publishes a sample; false if Fast DDS refused it (e.g. resources exhausted). There is no
  // unregister: in Fast DDS 2.9 it can make a reliable writer drop another sample unsent (see
  // RegionPublisher::publish).
  bool write(const Sample& s) const { return writer_->write(const_cast<Sample*>(&s)); }
  bool valid() const { return writer_ != nullptr; }
  // Blocks until every matched reliable reader has acknowledged every sample written so far, or
  // `timeout` has passed; true in the first case.
  bool wait_for_acknowledgments(std::chrono::milliseconds timeout) const {
    const eprosima::fastrtps::Duration_t limit(std::chrono::duration<long double>(timeout).count());
    return writer_->wait_for_acknowledgments(limit) == ReturnCode_t::RETCODE_OK;
  }

 private:
  fdds::DataWriter* writer_ = nullptr;
};

// Faults a participant injects into what it sends. Any fault makes it send over UDP only, without
// data sharing, and its writers heartbeat every 0.1 s, so that reliability has to repair each loss
// and does so within a lockstep step (node.cpp).
struct Faults {
  // A share (0-100 %) of the RTPS messages carrying user data (DATA, DATA_FRAG; not discovery).
  int drop_percent = 0;
  // Tests: drops each outgoing RTPS message carrying user data (DATA) for which it returns true;
  // it sees the whole message, header included.
  std::function<bool(const std::uint8_t* message, std::size_t size)> drop_message;

  bool any() const { return drop_percent > 0 || drop_message != nullptr; }
  // From ENTOURAGE_FAULT_DROP_PERCENT=N (a whole number 0-100; unset or empty: 0). Throws DdsError.
  static Faults from_environment();
};

class Node {
 public:
  // Loads the QoS profiles and joins `domain`. Throws DdsError with a clear message on failure.
  Node(int domain, const std::string& qos_file, const std::string& participant_name,
       Faults faults = Faults::from_environment());
  ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  template <class PubSubT>
  Writer<PubSubT> writer(Topic t) {
    return Writer<PubSubT>(create_writer(t, topic<PubSubT>(t)));
  }

  template <class PubSubT>
  void reader(Topic t, std::function<void(const typename PubSubT::type&)> on_sample) {
    auto listener = std::make_unique<TypedListener<PubSubT>>(std::move(on_sample));
    create_reader(t, topic<PubSubT>(t), listener.get());
    listeners_.push_back(std::move(listener));
  }

  // Matched endpoints in other participants of this node's reader / writer of a topic.
  int matched_writers(Topic t) const;
  int matched_readers(Topic t) const;

 private:
  template <class PubSubT>
  class TypedListener : public fdds::DataReaderListener {
   public:
    explicit TypedListener(std::function<void(const typename PubSubT::type&)> cb) : cb_(std::move(cb)) {}
    void on_data_available(fdds::DataReader* reader) override {
      typename PubSubT::type sample;
      fdds::SampleInfo info;
      while (reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
        if (info.valid_data) cb_(sample);
      }
    }

   private:
    std::function<void(const typename PubSubT::type&)> cb_;
  };

  template <class PubSubT>
  fdds::Topic* topic(Topic t) {
    auto it = topics_.find(t);
    if (it != topics_.end()) return it->second;
    fdds::TypeSupport type(new PubSubT());
    type.register_type(participant_);
    return register_topic(t, type.get_type_name());
  }

  fdds::Topic* register_topic(Topic t, const std::string& type_name);
  fdds::DataWriter* create_writer(Topic t, fdds::Topic* topic);
  void create_reader(Topic t, fdds::Topic* topic, fdds::DataReaderListener* listener);

  bool faulty_ = false;  // faults injected (Faults::any()), see node.cpp
  fdds::DomainParticipant* participant_ = nullptr;
  fdds::Publisher* publisher_ = nullptr;
  fdds::Subscriber* subscriber_ = nullptr;
  std::map<Topic, fdds::Topic*> topics_;
  std::map<Topic, fdds::DataWriter*> writers_;
  std::map<Topic, fdds::DataReader*> readers_;
  std::vector<std::unique_ptr<fdds::DataReaderListener>> listeners_;
};

}  // namespace entourage::dds
