#pragma once
// The UDP ports a DDS domain listens on, against the machine's ephemeral port range.
//
// Fast DDS's default port mapping (the RTPS specification's default port numbers, 9.6.1): port base 7400, domain gain 250,
// participant gain 2, offsets 0 (discovery multicast), 1 (user multicast), 10 and 11 (discovery
// and user unicast, plus 2 per participant id). The kernel gives every socket bound to port 0 (the
// send sockets of every process on the host) a random port from the ephemeral range
// (/proc/sys/net/ipv4/ip_local_port_range, 32768-60999 by default). If one of those holds a
// domain's discovery multicast port before a participant binds it, that participant discovers
// nobody: with the range's defaults, domains 0-101 are clear of it. `entourage run` and every
// service warn at the start when their domain is not (the run goes on: the range is the host's).

#include <optional>
#include <string>

namespace entourage::dds {

struct PortRange {
  int first = 0;
  int last = 0;  // inclusive
};

constexpr int kPortBase = 7400;
constexpr int kDomainGain = 250;
constexpr int kParticipantGain = 2;
constexpr int kUserUnicastOffset = 11;  // the highest of the four offsets
// Participant ids on one host checked: the launcher, its services, a simulator and some more.
constexpr int kParticipantsChecked = 32;
constexpr const char* kEphemeralRangeFile = "/proc/sys/net/ipv4/ip_local_port_range";

// The well-known ports of `domain` for the first kParticipantsChecked participants on a host.
constexpr PortRange domain_ports(int domain) {
  const int base = kPortBase + kDomainGain * domain;
  return {base, base + kUserUnicastOffset + kParticipantGain * (kParticipantsChecked - 1)};
}

// Linux's default ephemeral port range (ip_local_port_range).
constexpr PortRange kLinuxEphemeralDefault{32768, 60999};

// The contents of ip_local_port_range ("32768\t60999\n"), or nullopt if they are not two ports.
std::optional<PortRange> parse_port_range(const std::string& text);

// The highest domain whose ports all lie below the ephemeral range (-1: none does).
constexpr int highest_clear_domain(const PortRange& ephemeral) {
  const int room = ephemeral.first - 1 - domain_ports(0).last;  // below it, beyond domain 0's ports
  return room < 0 ? -1 : room / kDomainGain;
}

// A warning if the domain's ports fall in the ephemeral range, else empty.
std::string ephemeral_clash(int domain, const PortRange& ephemeral);

// The same against this host's range (kEphemeralRangeFile); empty where it cannot be read.
std::string ephemeral_clash_here(int domain);

}  // namespace entourage::dds
