#include "dds/node.hpp"

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/rtps/transport/test_UDPv4TransportDescriptor.h>

#include <cstdlib>
#include <memory>

namespace entourage::dds {

namespace {
constexpr const char* kParticipantProfile = "entourage_participant";
constexpr const char* kDropEnv = "ENTOURAGE_FAULT_DROP_PERCENT";
constexpr std::uint32_t kLossyHeartbeat_ns = 100000000;

std::string profile_of(Topic t, const char* side) { return std::string(info(t).profile) + "_" + side; }
}  // namespace

// Fault injection: ENTOURAGE_FAULT_DROP_PERCENT=N (1-100) makes this process's participant send
// over UDP only, dropping N % of its outgoing data messages (RTPS DATA and DATA_FRAG; discovery
// is not dropped), and turns data sharing off, so that reliability has to repair every loss.
// 0 or unset: the normal transports.
Faults Faults::from_environment() {
  Faults f;
  const char* v = std::getenv(kDropEnv);
  if (v == nullptr || *v == '\0') return f;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  if (*end != '\0' || n < 0 || n > 100) {
    throw DdsError(std::string(kDropEnv) + " must be a whole number from 0 to 100 (got \"" + v + "\")");
  }
  f.drop_percent = static_cast<int>(n);
  return f;
}

Node::Node(int domain, const std::string& qos_file, const std::string& participant_name, Faults faults) {
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  if (factory->load_XML_profiles_file(qos_file) != ReturnCode_t::RETCODE_OK) {
    throw DdsError("cannot load the QoS profiles from " + qos_file);
  }
  fdds::DomainParticipantQos qos;
  if (factory->get_participant_qos_from_profile(kParticipantProfile, qos) != ReturnCode_t::RETCODE_OK) {
    throw DdsError(std::string("the QoS file ") + qos_file + " has no participant profile " + kParticipantProfile);
  }
  qos.name(participant_name);
  faulty_ = faults.any();
  if (faulty_) {
    auto lossy = std::make_shared<eprosima::fastdds::rtps::test_UDPv4TransportDescriptor>();
    lossy->dropDataMessagesPercentage = static_cast<std::uint8_t>(faults.drop_percent);
    if (faults.drop_message) {
      using eprosima::fastrtps::rtps::CDRMessage_t;
      lossy->drop_data_messages_filter_ = [drop = std::move(faults.drop_message)](CDRMessage_t& m) {
        return drop(m.buffer, m.length);
      };
    }
    qos.transport().user_transports.push_back(lossy);
    qos.transport().use_builtin_transports = false;
  }
  participant_ = factory->create_participant(static_cast<fdds::DomainId_t>(domain), qos);
  if (participant_ == nullptr) throw DdsError("cannot join DDS domain " + std::to_string(domain));
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (publisher_ == nullptr || subscriber_ == nullptr) throw DdsError("cannot create a publisher or subscriber");
}

Node::~Node() {
  if (participant_ == nullptr) return;
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

fdds::Topic* Node::register_topic(Topic t, const std::string& type_name) {
  fdds::Topic* topic = participant_->create_topic(std::string(info(t).name), type_name, fdds::TOPIC_QOS_DEFAULT);
  if (topic == nullptr) throw DdsError("cannot create topic " + std::string(info(t).name));
  topics_[t] = topic;
  return topic;
}

fdds::DataWriter* Node::create_writer(Topic t, fdds::Topic* topic) {
  fdds::DataWriterQos qos;
  if (publisher_->get_datawriter_qos_from_profile(profile_of(t, "writer"), qos) != ReturnCode_t::RETCODE_OK) {
    throw DdsError("no QoS profile " + profile_of(t, "writer"));
  }
  // Not settable from XML in Fast DDS 2.9: a vehicle handed to another owner must not be disposed.
  // (Regions no longer unregister handed-on vehicles at all, region_shell.hpp; kept so that no
  // future unregister disposes one.)
  qos.writer_data_lifecycle().autodispose_unregistered_instances = false;
  if (faulty_) {
    qos.data_sharing().off();
    // A loss is noticed at the next heartbeat: 0.1 s instead of the default 3 s, so that a lockstep
    // step waits a fraction of a second for a repair. (Not by default: it halves the lockstep
    // speed, 349 against 163 steps/s on the default scenario.)
    qos.reliable_writer_qos().times.heartbeatPeriod = eprosima::fastrtps::Duration_t(0, kLossyHeartbeat_ns);
  }
  fdds::DataWriter* w = publisher_->create_datawriter(topic, qos);
  if (w == nullptr) throw DdsError("cannot create a writer for " + std::string(info(t).name));
  writers_[t] = w;
  return w;
}

void Node::create_reader(Topic t, fdds::Topic* topic, fdds::DataReaderListener* listener) {
  fdds::DataReaderQos qos;
  if (subscriber_->get_datareader_qos_from_profile(profile_of(t, "reader"), qos) != ReturnCode_t::RETCODE_OK) {
    throw DdsError("no QoS profile " + profile_of(t, "reader"));
  }
  if (faulty_) qos.data_sharing().off();
  fdds::DataReader* r = subscriber_->create_datareader(topic, qos, listener, fdds::StatusMask::data_available());
  if (r == nullptr) throw DdsError("cannot create a reader for " + std::string(info(t).name));
  readers_[t] = r;
}

// Fast DDS 2.9 does not implement get_matched_publications/subscriptions (RETCODE_UNSUPPORTED),
// and its matched counts include the participant's own endpoint of the other kind on the topic.
int Node::matched_writers(Topic t) const {
  auto it = readers_.find(t);
  if (it == readers_.end()) return 0;
  fdds::SubscriptionMatchedStatus s;
  it->second->get_subscription_matched_status(s);
  return s.current_count - (writers_.count(t) != 0 ? 1 : 0);
}

int Node::matched_readers(Topic t) const {
  auto it = writers_.find(t);
  if (it == writers_.end()) return 0;
  fdds::PublicationMatchedStatus s;
  it->second->get_publication_matched_status(s);
  return s.current_count - (readers_.count(t) != 0 ? 1 : 0);
}

}  // namespace entourage::dds
