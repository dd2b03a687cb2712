#include "dds/domain_ports.hpp"

#include <fstream>
#include <sstream>

namespace entourage::dds {

std::optional<PortRange> parse_port_range(const std::string& text) {
  std::istringstream in(text);
  PortRange r;
  std::string rest;
  if (!(in >> r.first >> r.last) || (in >> rest) || r.first < 1 || r.last > 65535 || r.first > r.last) {
    return std::nullopt;
  }
  return r;
}

std::string ephemeral_clash(int domain, const PortRange& ephemeral) {
  const PortRange ports = domain_ports(domain);
  if (ports.last < ephemeral.first || ports.first > ephemeral.last) return "";
  std::ostringstream m;
  m << "DDS domain " << domain << " listens on UDP ports " << ports.first << "-" << ports.last
    << ", inside this machine's ephemeral port range " << ephemeral.first << "-" << ephemeral.last
    << " (" << kEphemeralRangeFile << "): a random port of any process on this host can take one of"
       " them and stop discovery in this domain";
  const int highest = highest_clear_domain(ephemeral);
  if (highest >= 0) m << "; domains 0-" << highest << " are clear of it here";
  return m.str();
}

std::string ephemeral_clash_here(int domain) {
  std::ifstream in(kEphemeralRangeFile);
  std::stringstream text;
  text << in.rdbuf();
  const auto ephemeral = parse_port_range(text.str());
  return ephemeral ? ephemeral_clash(domain, *ephemeral) : "";
}

}  // namespace entourage::dds
