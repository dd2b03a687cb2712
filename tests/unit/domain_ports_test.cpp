// The check of a DDS domain's well-known ports against the ephemeral port range
// (common/dds/domain_ports.hpp), and that every test domain is clear of the default range.
#include <gtest/gtest.h>

#include "../test_domains.hpp"
#include "dds/domain_ports.hpp"

namespace entourage::dds {
namespace {

TEST(DomainPorts, FollowTheDefaultPortMapping) {
  EXPECT_EQ(domain_ports(0).first, 7400);
  EXPECT_EQ(domain_ports(130).first, 7400 + 250 * 130);  // 39900: the flaky test's discovery port
  // Discovery and user unicast of participant id 31: 11 + 2·31 above the base.
  EXPECT_EQ(domain_ports(1).last, 7650 + 73);
}

TEST(DomainPorts, ReadTheKernelsRange) {
  const auto r = parse_port_range("32768\t60999\n");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->first, 32768);
  EXPECT_EQ(r->last, 60999);
  EXPECT_FALSE(parse_port_range("").has_value());
  EXPECT_FALSE(parse_port_range("32768").has_value());
  EXPECT_FALSE(parse_port_range("60999 32768").has_value());
  EXPECT_FALSE(parse_port_range("1 2 3").has_value());
  EXPECT_FALSE(parse_port_range("0 70000").has_value());
}

TEST(DomainPorts, WarnOnlyWhereTheRangeReaches) {
  EXPECT_EQ(highest_clear_domain(kLinuxEphemeralDefault), 101);
  EXPECT_TRUE(ephemeral_clash(0, kLinuxEphemeralDefault).empty());
  EXPECT_TRUE(ephemeral_clash(101, kLinuxEphemeralDefault).empty());
  const std::string w = ephemeral_clash(102, kLinuxEphemeralDefault);
  EXPECT_NE(w.find("ports 32900-32973"), std::string::npos) << w;
  EXPECT_NE(w.find("domains 0-101"), std::string::npos) << w;
  EXPECT_FALSE(ephemeral_clash(130, kLinuxEphemeralDefault).empty());
  EXPECT_FALSE(ephemeral_clash(214, kLinuxEphemeralDefault).empty());  // 60900-60973
  EXPECT_TRUE(ephemeral_clash(215, kLinuxEphemeralDefault).empty());   // 61150 on: above the range
  // A host with the range moved up clears more domains; one that starts below every domain, none.
  EXPECT_TRUE(ephemeral_clash(130, PortRange{49152, 65535}).empty());
  EXPECT_EQ(highest_clear_domain(PortRange{7474, 65535}), 0);
  EXPECT_EQ(highest_clear_domain(PortRange{7473, 65535}), -1);
  EXPECT_EQ(highest_clear_domain(PortRange{1024, 65535}), -1);
  const std::string none = ephemeral_clash(0, PortRange{1024, 65535});
  EXPECT_FALSE(none.empty());
  EXPECT_EQ(none.find("domains 0-"), std::string::npos) << none;
}

TEST(DomainPorts, EveryTestDomainIsClearOfTheDefaultRange) {
  for (int d = testing::test_domain::kPipelineLockstep; d < testing::test_domain::kEnd; ++d) {
    EXPECT_TRUE(ephemeral_clash(d, kLinuxEphemeralDefault).empty()) << "test domain " << d;
  }
}

}  // namespace
}  // namespace entourage::dds
