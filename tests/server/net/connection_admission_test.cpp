// Connection admission and refusals without sockets: the counts a ticket
// holds, through a hand-over (an upgrade) and back, and the bytes a
// refused connection is sent.
#include <vector>

#include <gtest/gtest.h>

#include "connection_admission.hpp"
#include "connection_refusal.hpp"
#include "descriptor_reserve.hpp"
#include "fw/codec/messages.hpp"

namespace fw::server {
namespace {

AbuseLimits limits_of(std::size_t per_address) {
  AbuseLimits limits;
  limits.connections_per_address = per_address;
  return limits;
}

TEST(ConnectionAdmission, AnAddressHoldsItsShareAndNoMore) {
  AddressLimits addresses(limits_of(2));
  ConnectionAdmission admission(addresses, 100);
  auto first = admission.admit("10.0.0.1");
  auto second = admission.admit("10.0.0.1");
  ASSERT_TRUE(first.ticket && second.ticket);
  const auto third = admission.admit("10.0.0.1");
  EXPECT_FALSE(third.ticket);
  EXPECT_EQ(third.refusal, Abuse::address_connection_limit);
  EXPECT_TRUE(admission.admit("10.0.0.2").ticket) << "another address has its own share";
  EXPECT_EQ(admission.open(), 2u) << "the refused one and the ended one are not counted";
  first.ticket.reset();
  EXPECT_TRUE(admission.admit("10.0.0.1").ticket) << "a closed connection gives its place back";
}

TEST(ConnectionAdmission, TheListenerHoldsItsTotalAndNoMore) {
  AddressLimits addresses(limits_of(10));
  ConnectionAdmission admission(addresses, 2);
  auto a = admission.admit("10.0.0.1");
  auto b = admission.admit("10.0.0.2");
  const auto c = admission.admit("10.0.0.3");
  EXPECT_FALSE(c.ticket);
  EXPECT_EQ(c.refusal, Abuse::connection_limit);
  EXPECT_EQ(addresses.connections("10.0.0.3"), 0u) << "nothing counted against the refused address";
}

TEST(ConnectionAdmission, ATicketHandedOnKeepsCountingUntilTheLastOwnerLetsGo) {
  AddressLimits addresses(limits_of(5));
  ConnectionAdmission admission(addresses, 100);
  auto admitted = admission.admit("10.0.0.1");
  ConnectionTicket http = std::move(*admitted.ticket);
  admitted.ticket.reset();
  EXPECT_EQ(addresses.connections("10.0.0.1"), 1u);
  {
    ConnectionTicket websocket = std::move(http);  // the upgrade
    EXPECT_EQ(addresses.connections("10.0.0.1"), 1u);
    EXPECT_EQ(admission.open(), 1u);
    EXPECT_EQ(websocket.address(), "10.0.0.1");
  }
  EXPECT_EQ(addresses.connections("10.0.0.1"), 0u);
  EXPECT_EQ(admission.open(), 0u);
}

// A trusted proxy's connection counts in the total only; each request's
// client is counted once its header names it, and between requests nobody.
TEST(ConnectionAdmission, AProxysConnectionCountsAgainstTheClientItForwards) {
  AddressLimits addresses(limits_of(2));
  ConnectionAdmission admission(addresses, 100);
  std::vector<ConnectionTicket> proxied;
  for (int i = 0; i < 5; ++i) {
    auto admitted = admission.admit_from_trusted_proxy();
    ASSERT_TRUE(admitted.ticket) << "a proxy is not held to one address's share (2): " << i;
    EXPECT_EQ(admitted.ticket->address(), "");
    proxied.push_back(std::move(*admitted.ticket));
  }
  EXPECT_EQ(admission.open(), 5u);
  EXPECT_TRUE(proxied[0].count_against(addresses, "203.0.113.1"));
  EXPECT_TRUE(proxied[1].count_against(addresses, "203.0.113.1"));
  EXPECT_FALSE(proxied[2].count_against(addresses, "203.0.113.1")) << "the client holds its share";
  EXPECT_EQ(proxied[2].address(), "");
  EXPECT_TRUE(proxied[2].count_against(addresses, "203.0.113.2")) << "another client has its own";
  EXPECT_TRUE(proxied[0].count_against(addresses, "203.0.113.1")) << "the same client again: nothing more";
  EXPECT_EQ(addresses.connections("203.0.113.1"), 2u);
  proxied[0].release_address();  // the request answered; the connection idles
  EXPECT_EQ(addresses.connections("203.0.113.1"), 1u);
  EXPECT_TRUE(proxied[1].count_against(addresses, "203.0.113.3")) << "the next request is another client's";
  EXPECT_EQ(addresses.connections("203.0.113.1"), 0u);
  proxied.clear();
  EXPECT_EQ(admission.open(), 0u);
  EXPECT_EQ(addresses.connections("203.0.113.2") + addresses.connections("203.0.113.3"), 0u);
}

TEST(ConnectionRefusal, HttpSaysWhyAndWhenToComeBack) {
  const std::string address = http_refusal(Abuse::address_connection_limit, 64, std::chrono::seconds(7));
  EXPECT_EQ(address.rfind("HTTP/1.1 429 ", 0), 0u);
  EXPECT_NE(address.find("Retry-After: 7\r\n"), std::string::npos);
  EXPECT_NE(address.find("at most 64 at once"), std::string::npos);
  EXPECT_NE(address.find("try again in 7 s"), std::string::npos);
  const auto body = address.substr(address.find("\r\n\r\n") + 4);
  EXPECT_NE(address.find("Content-Length: " + std::to_string(body.size()) + "\r\n"), std::string::npos);
  const std::string block = http_refusal(Abuse::block_connection_limit, 256, std::chrono::seconds(3));
  EXPECT_EQ(block.rfind("HTTP/1.1 429 ", 0), 0u);
  EXPECT_NE(block.find("from your network (at most 256 at once)"), std::string::npos);
  EXPECT_EQ(http_refusal(Abuse::descriptors_exhausted, 64, std::chrono::seconds(2)).rfind("HTTP/1.1 503 ", 0), 0u);
  const std::string full = http_refusal(Abuse::connection_limit, 64, std::chrono::seconds(9));
  EXPECT_EQ(full.rfind("HTTP/1.1 503 ", 0), 0u);
  EXPECT_NE(full.find("Retry-After: 9\r\n"), std::string::npos);
  EXPECT_NE(full.find("try again in 9 s"), std::string::npos);
}

TEST(ConnectionRefusal, TcpSendsAClosingMessage) {
  const std::string framed = tcp_refusal(Abuse::address_connection_limit, 8, std::chrono::seconds(4));
  codec::TcpDeframer deframer{codec::kMaxDownstreamMessageBytes};
  deframer.feed({reinterpret_cast<const std::uint8_t*>(framed.data()), framed.size()});
  std::span<const std::uint8_t> message;
  ASSERT_EQ(deframer.next(message), codec::TcpDeframer::Status::message);
  codec::Closing closing;
  ASSERT_EQ(codec::read_message(message, closing), codec::MessageError::ok);
  EXPECT_EQ(closing.code, codec::CloseCode::rate_limited);
  EXPECT_NE(closing.reason.find("too many connections"), std::string::npos);
  EXPECT_NE(closing.reason.find("try again in 4 s"), std::string::npos);
  EXPECT_LE(closing.reason.size(), codec::kMaxReasonBytes);
  const std::string full = tcp_refusal(Abuse::connection_limit, 8, std::chrono::seconds(6));
  deframer = codec::TcpDeframer{codec::kMaxDownstreamMessageBytes};
  deframer.feed({reinterpret_cast<const std::uint8_t*>(full.data()), full.size()});
  ASSERT_EQ(deframer.next(message), codec::TcpDeframer::Status::message);
  ASSERT_EQ(codec::read_message(message, closing), codec::MessageError::ok);
  EXPECT_EQ(closing.code, codec::CloseCode::server_full);
  EXPECT_NE(closing.reason.find("try again in 6 s"), std::string::npos);
}

TEST(ConnectionAdmission, ABlockHoldsItsShareOfThePortAndTheAddressIsNotCharged) {
  AddressLimits addresses(limits_of(10));
  ConnectionAdmission admission(addresses, ConnectionShareLimits{100, 2, 0});
  auto a = admission.admit("10.0.0.1");
  auto b = admission.admit("10.0.0.2");
  ASSERT_TRUE(a.ticket && b.ticket);
  const auto c = admission.admit("10.0.0.3");
  EXPECT_FALSE(c.ticket);
  EXPECT_EQ(c.refusal, Abuse::block_connection_limit);
  EXPECT_EQ(addresses.connections("10.0.0.3"), 0u) << "nothing counted against the refused address";
  EXPECT_TRUE(admission.admit("10.0.1.3").ticket) << "the next /24";
}

TEST(ConnectionAdmission, ATicketThatGaveItsPlaceUpIsClosedAndCountedNoMore) {
  AddressLimits addresses(limits_of(10));
  ConnectionAdmission admission(addresses, ConnectionShareLimits{2, 100, 0});
  auto a = admission.admit("10.0.0.1");
  auto b = admission.admit("10.0.0.2");
  bool closed = false;
  a.ticket->on_evict([&closed] { closed = true; });
  b.ticket->busy();
  const auto person = admission.admit("192.0.2.1");
  ASSERT_TRUE(person.ticket);
  EXPECT_EQ(person.evicted, "10.0.0.1");
  EXPECT_TRUE(closed);
  EXPECT_EQ(admission.open(), 2u);
  EXPECT_EQ(addresses.connections("10.0.0.1"), 1u) << "its address counts it until it is gone";
  a.ticket.reset();
  EXPECT_EQ(addresses.connections("10.0.0.1"), 0u);
  EXPECT_EQ(admission.open(), 2u);
}

TEST(DescriptorLimit, EachPortGetsItsPartOfTheOpenFilesLimit) {
  EXPECT_EQ(connections_per_port(1024, 2, 2048), (1024 - kDescriptorsForFiles) / 2);
  EXPECT_EQ(connections_per_port(1024, 1, 2048), 1024 - kDescriptorsForFiles);
  EXPECT_EQ(connections_per_port(1u << 20, 2, 2048), 2048u) << "never more than asked";
  EXPECT_EQ(connections_per_port(10, 2, 2048), 1u) << "at least one";
}

}  // namespace
}  // namespace fw::server
