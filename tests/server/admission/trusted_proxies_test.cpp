// Trusted proxies without sockets: the ranges --trusted-proxy takes (and the
// errors it gives), and which address of a forwarding header is the client:
// the rightmost that is not a trusted proxy, what a client wrote to its left
// never read, and nothing read at all from a peer that is not trusted.
#include <gtest/gtest.h>

#include "trusted_proxies.hpp"

namespace fw::server {
namespace {

namespace ip = boost::asio::ip;
using Source = ClientAddress::Source;

ip::address addr(const char* text) { return ip::make_address(text); }

AddressRange range(const char* text) {
  std::string error;
  const auto parsed = parse_address_range(text, error);
  EXPECT_TRUE(parsed) << text << ": " << error;
  return parsed.value_or(AddressRange{});
}

std::string range_error(const char* text) {
  std::string error;
  EXPECT_FALSE(parse_address_range(text, error)) << text << " was taken";
  return error;
}

TrustedProxies trusting(std::initializer_list<const char*> ranges) {
  TrustedProxies proxies;
  std::string error;
  for (const char* r : ranges) EXPECT_TRUE(proxies.add(r, error)) << error;
  return proxies;
}

ClientAddress from(const TrustedProxies& proxies, const char* peer, std::vector<std::string_view> x_forwarded_for,
                   std::vector<std::string_view> forwarded = {}) {
  return client_address(proxies, addr(peer), {std::move(x_forwarded_for), std::move(forwarded)});
}

TEST(AddressRange, ParsesIpv4AndIpv6NetworksAndSingleAddresses) {
  EXPECT_EQ(range("10.0.0.0/8").to_string(), "10.0.0.0/8");
  EXPECT_EQ(range("fd00::/8").to_string(), "fd00::/8");
  EXPECT_EQ(range("127.0.0.1").to_string(), "127.0.0.1/32");
  EXPECT_EQ(range("2001:db8::5").to_string(), "2001:db8::5/128");
  EXPECT_EQ(range(" 192.168.0.0/16 ").to_string(), "192.168.0.0/16")
      << "spaces after a comma in FACEWIRE_TRUSTED_PROXY";
  EXPECT_EQ(range("0.0.0.0/0").to_string(), "0.0.0.0/0");
  EXPECT_EQ(range("::ffff:10.0.0.0/104").to_string(), "10.0.0.0/8") << "IPv4 written as mapped IPv6";
}

TEST(AddressRange, RefusesWhatIsNoRangeAndSaysWhatToWrite) {
  EXPECT_NE(range_error("10.0.0.1/8").find("write the network, 10.0.0.0/8, or 10.0.0.1/32"), std::string::npos)
      << range_error("10.0.0.1/8");
  EXPECT_NE(range_error("10.0.0.0/33").find("from 0 to 32"), std::string::npos);
  EXPECT_NE(range_error("fd00::/129").find("from 0 to 128"), std::string::npos);
  EXPECT_NE(range_error("10.0.0.0/").find("prefix length"), std::string::npos);
  EXPECT_NE(range_error("10.0.0.0/-1").find("prefix length"), std::string::npos);
  EXPECT_NE(range_error("proxy.example/24").find("no IPv4 or IPv6 address"), std::string::npos);
  EXPECT_NE(range_error("").find("empty"), std::string::npos);
  EXPECT_NE(range_error("10.0.0").find("ADDRESS/PREFIX"), std::string::npos);
}

TEST(AddressRange, ContainsItsAddressesOnly) {
  const AddressRange ten = range("10.0.0.0/8");
  EXPECT_TRUE(ten.contains(addr("10.1.2.3")));
  EXPECT_TRUE(ten.contains(addr("10.255.255.255")));
  EXPECT_FALSE(ten.contains(addr("11.0.0.0")));
  EXPECT_TRUE(ten.contains(addr("::ffff:10.0.0.7"))) << "what a dual-stack listener sees";
  EXPECT_FALSE(ten.contains(addr("::a00:7"))) << "an IPv6 address is not an IPv4 one";
  const AddressRange v6 = range("2001:db8:0:1::/64");
  EXPECT_TRUE(v6.contains(addr("2001:db8:0:1:ffff::1")));
  EXPECT_FALSE(v6.contains(addr("2001:db8:0:2::1")));
  EXPECT_FALSE(v6.contains(addr("10.0.0.1")));
  const AddressRange odd = range("192.168.4.0/22");
  EXPECT_TRUE(odd.contains(addr("192.168.7.255")));
  EXPECT_FALSE(odd.contains(addr("192.168.8.0")));
  EXPECT_TRUE(range("0.0.0.0/0").contains(addr("203.0.113.9")));
}

TEST(ClientAddress, APeerThatIsNoTrustedProxyIsTheClientWhateverItSends) {
  const auto proxies = trusting({"127.0.0.1/32"});
  const auto spoofed = from(proxies, "127.0.0.2", {"203.0.113.7"}, {"for=198.51.100.1"});
  EXPECT_EQ(spoofed.source, Source::peer);
  EXPECT_EQ(spoofed.address, addr("127.0.0.2"));
  const auto no_proxies = from(TrustedProxies{}, "127.0.0.1", {"203.0.113.7"});
  EXPECT_EQ(no_proxies.address, addr("127.0.0.1")) << "without --trusted-proxy nobody's header counts";
  EXPECT_EQ(from(proxies, "127.0.0.2", {"not an address"}).source, Source::peer) << "nor is it checked";
}

TEST(ClientAddress, ATrustedProxysClientIsTheRightmostUntrustedAddress) {
  const auto proxies = trusting({"127.0.0.1", "10.0.0.0/8"});
  const auto one = from(proxies, "127.0.0.1", {"203.0.113.7"});
  EXPECT_EQ(one.source, Source::forwarded);
  EXPECT_EQ(one.address, addr("203.0.113.7"));
  // What the client itself sent stands to the left of what the proxy appended.
  EXPECT_EQ(from(proxies, "127.0.0.1", {"198.51.100.1, 203.0.113.7"}).address, addr("203.0.113.7"));
  // Proxies behind proxies: their own addresses are skipped.
  EXPECT_EQ(from(proxies, "127.0.0.1", {"198.51.100.1, 203.0.113.7,10.0.0.2 , 10.9.9.9"}).address,
            addr("203.0.113.7"));
  // A client inside the proxies' own network: the leftmost.
  EXPECT_EQ(from(proxies, "127.0.0.1", {"10.0.0.3, 10.0.0.2"}).address, addr("10.0.0.3"));
  // Several header lines are one list, in order.
  EXPECT_EQ(from(proxies, "127.0.0.1", {"198.51.100.1", "203.0.113.8"}).address, addr("203.0.113.8"));
  // A dual-stack listener's view of the proxy, and an IPv4 client written as mapped IPv6.
  EXPECT_EQ(from(proxies, "::ffff:127.0.0.1", {"::ffff:203.0.113.9"}).address, addr("203.0.113.9"));
  // No header: the proxy's own request (a health check).
  const auto direct = from(proxies, "127.0.0.1", {});
  EXPECT_EQ(direct.source, Source::peer);
  EXPECT_EQ(direct.address, addr("127.0.0.1"));
}

TEST(ClientAddress, AddressesMayCarryPortsAndBrackets) {
  const auto proxies = trusting({"127.0.0.1"});
  EXPECT_EQ(from(proxies, "127.0.0.1", {"203.0.113.7:4711"}).address, addr("203.0.113.7"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {"2001:db8::1"}).address, addr("2001:db8::1"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {"[2001:db8::1]"}).address, addr("2001:db8::1"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {"[2001:db8::1]:4711"}).address, addr("2001:db8::1"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {"203.0.113.7:port"}).source, Source::malformed);
  EXPECT_EQ(from(proxies, "127.0.0.1", {"[2001:db8::1"}).source, Source::malformed);
  EXPECT_EQ(from(proxies, "127.0.0.1", {"[203.0.113.7]"}).source, Source::malformed);
}

TEST(ClientAddress, AMalformedHeaderFromATrustedProxyCountsAsTheProxy) {
  const auto proxies = trusting({"127.0.0.1"});
  const auto garbage = from(proxies, "127.0.0.1", {"203.0.113.7, garbage\x01"});
  EXPECT_EQ(garbage.source, Source::malformed);
  EXPECT_EQ(garbage.address, addr("127.0.0.1"));
  EXPECT_EQ(garbage.problem, "X-Forwarded-For: 'garbage?' is not an address") << "printable in a log line";
  EXPECT_EQ(from(proxies, "127.0.0.1", {""}).source, Source::malformed);
  EXPECT_EQ(from(proxies, "127.0.0.1", {" , "}).problem, "X-Forwarded-For names no address");
  EXPECT_EQ(from(proxies, "127.0.0.1", {"unknown"}).source, Source::malformed);
  // Garbage the client wrote left of the proxy's entry is never read: it
  // cannot push the client into the proxy's share.
  const auto left_garbage = from(proxies, "127.0.0.1", {"garbage, 203.0.113.7"});
  EXPECT_EQ(left_garbage.source, Source::forwarded);
  EXPECT_EQ(left_garbage.address, addr("203.0.113.7"));
}

TEST(ClientAddress, ForwardedForCountsWhenThereIsNoXForwardedFor) {
  const auto proxies = trusting({"127.0.0.1"});
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"for=192.0.2.60;proto=http;by=203.0.113.43"}).address,
            addr("192.0.2.60"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"For=\"[2001:db8:cafe::17]:4711\""}).address, addr("2001:db8:cafe::17"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"for=192.0.2.43, for=198.51.100.17;proto=https"}).address,
            addr("198.51.100.17"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"proto=https;for=\"198.51.100.17:80\""}).address,
            addr("198.51.100.17"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"for=192.0.2.43", "for=198.51.100.18"}).address, addr("198.51.100.18"));
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"for=192.0.2.43, for=198.51.100.19;by=\"_a,b\""}).address,
            addr("198.51.100.19")) << "a comma inside quotes splits nothing";
  const auto unknown = from(proxies, "127.0.0.1", {}, {"for=unknown"});
  EXPECT_EQ(unknown.source, Source::malformed);
  EXPECT_EQ(unknown.problem, "Forwarded: 'unknown' is not an address");
  EXPECT_EQ(from(proxies, "127.0.0.1", {}, {"proto=https"}).source, Source::malformed);
  EXPECT_EQ(from(proxies, "127.0.0.1", {"203.0.113.7"}, {"for=198.51.100.17"}).address, addr("203.0.113.7"))
      << "X-Forwarded-For wins";
}

}  // namespace
}  // namespace fw::server
