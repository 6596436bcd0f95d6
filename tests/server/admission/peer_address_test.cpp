// The keys under which limits count peers, without sockets: one address
// (an IPv6 /64), and the network block it shares with its neighbours (an
// IPv4 /24, an IPv6 /48), which is how the IPv6 grouping is tested.
#include "peer_address.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

TEST(PeerAddress, AnIpv6AddressCountsAsItsSlash64) {
  EXPECT_EQ(address_key("2001:db8:1:2:3:4:5:6"), "2001:db8:1:2::/64");
  EXPECT_EQ(address_key("2001:db8:1:2:ffff::1"), "2001:db8:1:2::/64");
  EXPECT_EQ(address_key("::ffff:192.0.2.7"), "192.0.2.7") << "mapped IPv4 counts as IPv4";
  EXPECT_EQ(address_key("not an address"), "not an address");
}

TEST(PeerAddress, Ipv4NeighboursShareTheirSlash24) {
  EXPECT_EQ(address_group("192.0.2.7"), "192.0.2.0/24");
  EXPECT_EQ(address_group("192.0.2.250"), "192.0.2.0/24");
  EXPECT_NE(address_group("192.0.3.7"), address_group("192.0.2.7"));
  EXPECT_EQ(address_group("::ffff:192.0.2.7"), "192.0.2.0/24") << "mapped IPv4 counts as IPv4";
  EXPECT_EQ(address_group("127.0.1.9"), "127.0.1.0/24");
}

TEST(PeerAddress, Ipv6NeighboursShareTheirSlash48) {
  // 256 /56s, or 65,536 /64s, of one site are one group.
  EXPECT_EQ(address_group("2001:db8:1:2:3:4:5:6"), "2001:db8:1::/48");
  EXPECT_EQ(address_group("2001:db8:1:ff00::1"), "2001:db8:1::/48");
  EXPECT_NE(address_group("2001:db8:2::1"), address_group("2001:db8:1::1"));
}

TEST(PeerAddress, AGroupIsFoundFromAnAddressKeyToo) {
  EXPECT_EQ(address_group(address_key("2001:db8:1:2:3:4:5:6")), "2001:db8:1::/48");
  EXPECT_EQ(address_group(address_key("192.0.2.7")), "192.0.2.0/24");
  EXPECT_EQ(address_group("not an address"), "not an address");
}

}  // namespace
}  // namespace fw::server
