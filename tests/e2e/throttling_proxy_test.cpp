#include "throttling_proxy.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <numeric>
#include <thread>

#include <gtest/gtest.h>

#include "loopback_socket.hpp"

namespace fw::test {
namespace {

using Clock = std::chrono::steady_clock;

// A listening socket on a free loopback port.
struct Listener {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  int port = 0;
  Listener() {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
    ::listen(fd, 4);
    socklen_t length = sizeof address;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    port = ntohs(address.sin_port);
  }
  ~Listener() { ::close(fd); }
  int accept_one() const { return ::accept(fd, nullptr, nullptr); }
};

int connect_to(int port) { return test::connect_loopback(port, 20); }

std::vector<std::uint8_t> pattern(std::size_t n) {
  std::vector<std::uint8_t> bytes(n);
  for (std::size_t i = 0; i < n; ++i) bytes[i] = static_cast<std::uint8_t>(i * 31 + 7);
  return bytes;
}

// Reads exactly `n` bytes (or fewer if the peer closes or 20 s pass).
std::vector<std::uint8_t> receive(int fd, std::size_t n) {
  std::vector<std::uint8_t> bytes(n);
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r = ::recv(fd, bytes.data() + got, n - got, 0);
    if (r <= 0) break;
    got += static_cast<std::size_t>(r);
  }
  bytes.resize(got);
  return bytes;
}

LinkShape shape(double bps, int delay_ms) {
  LinkShape link;
  link.bits_per_second = bps;
  link.delay = std::chrono::milliseconds(delay_ms);
  return link;
}

TEST(ThrottlingProxy, CarriesBytesIntactNoFasterThanTheRateAndNoSoonerThanTheDelay) {
  Listener target;
  ThrottlingProxy proxy("127.0.0.1", target.port, shape(19200, 300), shape(38400, 300));
  const int client = connect_to(proxy.port());
  ASSERT_GE(client, 0);
  const int server = target.accept_one();
  ASSERT_GE(server, 0);

  const auto up = pattern(2400);  // 1 s at 19.2 kbit/s
  const auto start = Clock::now();
  ASSERT_EQ(::send(client, up.data(), up.size(), MSG_NOSIGNAL), static_cast<ssize_t>(up.size()));
  const auto first = receive(server, 1);
  const double first_s = std::chrono::duration<double>(Clock::now() - start).count();
  const auto rest = receive(server, up.size() - 1);
  const double all_s = std::chrono::duration<double>(Clock::now() - start).count();
  std::vector<std::uint8_t> received = first;
  received.insert(received.end(), rest.begin(), rest.end());
  EXPECT_EQ(received, up);
  // Lower bounds only: the link may be slower on a busy machine, never faster.
  EXPECT_GE(first_s, 0.3) << "the one-way delay";
  EXPECT_GE(all_s, 0.3 + 2400 * 8 / 19200.0 - 0.02) << "the serialisation time at 19.2 kbit/s";

  const auto down = pattern(4800);  // 1 s at 38.4 kbit/s
  const auto down_start = Clock::now();
  ASSERT_EQ(::send(server, down.data(), down.size(), MSG_NOSIGNAL), static_cast<ssize_t>(down.size()));
  EXPECT_EQ(receive(client, down.size()), down);
  EXPECT_GE(std::chrono::duration<double>(Clock::now() - down_start).count(), 0.3 + 1.0 - 0.02);

  // The proxy counts a write when it completes, which the receiver may see
  // first: give the counters a moment to catch up.
  const auto settle = Clock::now() + std::chrono::seconds(2);
  while ((proxy.up().bytes_out != up.size() || proxy.down().bytes_out != down.size()) && Clock::now() < settle)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(proxy.up().bytes_out, up.size());
  EXPECT_EQ(proxy.down().bytes_out, down.size());
  EXPECT_EQ(proxy.down().bytes_in, down.size());
  ::close(client);
  ::close(server);
}

TEST(ThrottlingProxy, AFullQueuePushesBackOnTheSender) {
  Listener target;
  LinkShape down = shape(9600, 50);
  down.queue_bytes = 1024;
  ThrottlingProxy proxy("127.0.0.1", target.port, shape(9600, 50), down);
  const int client = connect_to(proxy.port());
  const int server = target.accept_one();
  ASSERT_GE(server, 0);
  // The server offers 400 KB at once; the link carries 1.2 KB/s. Its own
  // send buffer is kept small, as a server that watches its queues keeps it.
  const int send_buffer = 8192;
  ::setsockopt(server, SOL_SOCKET, SO_SNDBUF, &send_buffer, sizeof send_buffer);
  const int flags = MSG_NOSIGNAL | MSG_DONTWAIT;
  const auto bulk = pattern(400 * 1024);
  std::size_t sent = 0;
  for (int i = 0; i < 50; ++i) {
    const ssize_t n = ::send(server, bulk.data() + sent, bulk.size() - sent, flags);
    if (n > 0) sent += static_cast<std::size_t>(n);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_LT(sent, bulk.size()) << "the sender's socket filled up instead of the proxy buffering everything";
  const LinkCounters counters = proxy.down();
  EXPECT_GT(counters.queue_full_events, 0u);
  EXPECT_LE(counters.bytes_in - counters.bytes_out, down.queue_bytes + 2 * down.packet_bytes + 120)
      << "what the proxy holds stays near its queue (plus what is on the wire for the delay)";
  ::close(client);
  ::close(server);
}

TEST(ThrottlingProxy, DroppingConnectionsClosesBothEndsAndNewOnesStillWork) {
  Listener target;
  ThrottlingProxy proxy("127.0.0.1", target.port, shape(96000, 10), shape(96000, 10));
  const int client = connect_to(proxy.port());
  const int server = target.accept_one();
  ASSERT_GE(server, 0);
  proxy.drop_connections();
  char byte;
  EXPECT_LE(::recv(client, &byte, 1, 0), 0) << "the client sees the link go";
  EXPECT_LE(::recv(server, &byte, 1, 0), 0) << "the server sees the link go";
  ::close(client);
  ::close(server);

  const int again = connect_to(proxy.port());
  const int server_again = target.accept_one();
  ASSERT_GE(server_again, 0);
  const auto hello = pattern(10);
  ::send(again, hello.data(), hello.size(), MSG_NOSIGNAL);
  EXPECT_EQ(receive(server_again, hello.size()), hello);
  ::close(again);
  ::close(server_again);
}

}  // namespace
}  // namespace fw::test
