// Fair shares under many addresses, on the real server over loopback
// sockets from addresses spread over several /24s of 127.0.0.0/8: a crowd
// of a few dozen addresses cannot take every room; the last rooms wait for
// networks that hold none; a seat whose client neither sends nor reads is
// let go while a quiet watcher stays; and a crowd of half-sent requests or
// silent connections at a port's cap does not stop a person on a fresh
// address from getting /healthz and joining a room, while the crowd is
// told truthfully how long to wait.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "fw/codec/messages.hpp"
#include "loopback_socket.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"
#include "server_process.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using codec::CloseCode;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;

/// 127.0.`block`.`host`: each `block` a /24 of its own.
std::string loopback(int block, int host) { return "127.0." + std::to_string(block) + "." + std::to_string(host); }

template <class Server>
std::unique_ptr<RoomTestClient> join_from(const Server& server, Transport transport, const std::string& from,
                                          const std::string& room) {
  auto client = std::make_unique<RoomTestClient>(transport, server.port(transport), from);
  if (!client->connected()) return client;
  client->hello(room, "Someone");
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 10s);
  return client;
}

std::string outcome(const RoomTestClient& client) {
  if (client.welcome) return "welcomed";
  if (client.closing) return "closing " + std::to_string(static_cast<int>(client.closing->code)) + ": " +
                             client.closing->reason;
  return client.connected() ? "no answer" : "could not connect";
}

// --- raw sockets from a chosen loopback address ------------------------------

int connect_from(const std::string& source, int port) { return test::connect_loopback_from(source.c_str(), port, 0); }

using test::Received;
using test::receive_for;
using test::send_text;

/// GET `path` from `source`: the status (0 if none within `timeout`) and the whole answer.
std::pair<int, std::string> get_from(const std::string& source, int port, const std::string& path,
                                     std::chrono::milliseconds timeout = 5s) {
  const int fd = connect_from(source, port);
  if (fd < 0) return {0, "cannot connect"};
  send_text(fd, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  std::string text;
  const auto deadline = Clock::now() + timeout;
  Received r;
  do {
    r = receive_for(fd, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
    text += r.bytes;
  } while (!r.closed && Clock::now() < deadline);
  ::close(fd);
  if (text.rfind("HTTP/1.1 ", 0) != 0) return {0, text};
  return {std::atoi(text.c_str() + 9), text};
}

/// facewire_refusals_total{kind="`kind`"}, asked from `source`; -1 if absent.
long refusals(int port, const std::string& kind, const std::string& source) {
  const auto [status, text] = get_from(source, port, "/metrics");
  const std::string key = "facewire_refusals_total{kind=\"" + kind + "\"} ";
  const auto at = text.find(key);
  if (status != 200 || at == std::string::npos) return -1;
  return std::atol(text.c_str() + at + key.size());
}

// --- rooms -------------------------------------------------------------------

// The measured attack: 40 addresses took all 200 rooms of a --max-rooms 200
// server in a quarter of a second. Ten addresses in each of four /24s now
// hold their blocks' shares (20 rooms each by default) and no more.
TEST(FairShares, FortyAddressesInFourNetworksCannotTakeEveryRoom) {
  RunningServer server("--no-demo-room --max-rooms 200 --rooms-per-hour 100000");
  ASSERT_GT(server.tcp_port(), 0);
  constexpr int kBlocks = 4, kAddressesPerBlock = 10, kRoomsTried = 5;  // the burst of --rooms-per-hour
  constexpr int kRoomsPerBlock = 20;  // the default --rooms-per-block
  std::vector<std::unique_ptr<RoomTestClient>> held;
  int welcomed = 0, refused_by_share = 0;
  std::string a_refusal;
  const auto start = Clock::now();
  for (int block = 1; block <= kBlocks; ++block)
    for (int host = 1; host <= kAddressesPerBlock; ++host)
      for (int k = 0; k < kRoomsTried; ++k) {
        const std::string room = "squat-" + std::to_string(block) + "-" + std::to_string(host) + "-" + std::to_string(k);
        auto client = join_from(server, Transport::tcp, loopback(block, host), room);
        if (client->welcome) {
          ++welcomed;
          held.push_back(std::move(client));
        } else if (client->closing && client->closing->reason.find("rooms open already") != std::string::npos) {
          ++refused_by_share;
          a_refusal = client->closing->reason;
        } else {
          ADD_FAILURE() << room << ": " << outcome(*client);
        }
      }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  auto fresh = join_from(server, Transport::tcp, loopback(40, 1), "fresh");
  std::cout << kBlocks * kAddressesPerBlock << " addresses in " << kBlocks << " /24s tried "
            << kBlocks * kAddressesPerBlock * kRoomsTried << " rooms in " << seconds << " s: " << welcomed
            << " opened, " << refused_by_share << " refused by their shares (\"" << a_refusal
            << "\"); a fresh address in a fresh /24: " << outcome(*fresh) << "\n";
  EXPECT_EQ(welcomed, kBlocks * kRoomsPerBlock) << "each block holds its share, and no more";
  EXPECT_EQ(refused_by_share, kBlocks * kAddressesPerBlock * kRoomsTried - kBlocks * kRoomsPerBlock);
  EXPECT_TRUE(fresh->welcome) << "a fresh address in a fresh /24 still opens a room: " << outcome(*fresh);
  EXPECT_EQ(refusals(server.http_port(), "room_share", loopback(41, 1)), refused_by_share);
}

// The last tenth of the rooms opens only for a network that holds none:
// whoever squats the rest, from however many addresses of a few blocks,
// leaves them to everyone else.
TEST(FairShares, TheLastRoomsWaitForNetworksThatHoldNone) {
  RunningServer server(
      "--no-demo-room --max-rooms 50 --rooms-per-address 100 --rooms-per-block 100 --rooms-per-hour 100000 "
      "--joins-per-minute 100000");
  ASSERT_GT(server.tcp_port(), 0);
  std::vector<std::unique_ptr<RoomTestClient>> held;
  int welcomed = 0;
  std::string refusal;
  for (int i = 0; i < 60 && refusal.empty(); ++i) {
    // 15 addresses of one /24, each within its burst of new rooms.
    auto client = join_from(server, Transport::tcp, loopback(5, 1 + i % 15), "crowd" + std::to_string(i));
    if (client->welcome) {
      ++welcomed;
      held.push_back(std::move(client));
    } else {
      refusal = outcome(*client);
      EXPECT_EQ(client->closing ? client->closing->code : CloseCode::normal, CloseCode::server_full) << refusal;
    }
  }
  EXPECT_EQ(welcomed, 45) << "50 rooms, 10 % of them kept: " << refusal;
  EXPECT_NE(refusal.find("kept for networks that hold none"), std::string::npos) << refusal;
  auto first = join_from(server, Transport::tcp, loopback(6, 1), "first-of-its-network");
  EXPECT_TRUE(first->welcome) << outcome(*first);
  auto second = join_from(server, Transport::tcp, loopback(6, 2), "second-of-its-network");
  EXPECT_FALSE(second->welcome) << "its network holds one of the kept rooms now";
  auto other = join_from(server, Transport::tcp, loopback(7, 1), "another-network");
  EXPECT_TRUE(other->welcome) << outcome(*other);
  auto existing = join_from(server, Transport::tcp, loopback(5, 9), "crowd0");
  EXPECT_TRUE(existing->welcome) << "joining a room that exists opens none: " << outcome(*existing);
}

// --- seats held for nothing --------------------------------------------------

/// Rooms /api/rooms lists, asked from `source`.
std::string rooms_listed(int port, const std::string& source) { return get_from(source, port, "/api/rooms").second; }

// A squatter that pings but reads nothing is let go (here after 2 s), and
// its room, which nobody reads, closes with it; a watcher that reads but
// sends nothing but pings stays.
TEST(FairShares, ASeatWhoseClientNeitherSendsNorReadsIsLetGoAndAQuietWatcherStays) {
  RunningServer server("--no-demo-room --idle-seat-seconds 2");
  ASSERT_GT(server.tcp_port(), 0);
  RoomTestClient squatter(Transport::tcp, server.tcp_port(), loopback(8, 1));
  squatter.shrink_receive_buffer(2048);
  squatter.hello("squatted", "Squatter");
  ASSERT_TRUE(squatter.pump_until([&] { return squatter.welcome.has_value(); }, 10s));
  auto watcher = join_from(server, Transport::websocket, loopback(9, 1), "watched");
  ASSERT_TRUE(watcher->welcome) << outcome(*watcher);
  ASSERT_NE(rooms_listed(server.http_port(), loopback(10, 1)).find("squatted"), std::string::npos);

  // Both ping every second; only the watcher reads.
  const auto start = Clock::now();
  bool squatted_room_gone = false;
  double gone_after = -1;
  std::uint64_t watcher_bytes = 0;
  while (Clock::now() - start < 30s) {
    codec::Ping ping;
    ping.nonce = 1;
    squatter.send_message(ping);
    watcher->send_message(ping);
    const auto before = watcher->bytes_received;
    watcher->pump_for(1s);
    watcher_bytes += watcher->bytes_received - before;
    if (rooms_listed(server.http_port(), loopback(10, 1)).find("squatted") == std::string::npos) {
      squatted_room_gone = true;
      gone_after = std::chrono::duration<double>(Clock::now() - start).count();
      break;
    }
  }
  // A little longer, to see the watcher stay well past the threshold.
  for (int i = 0; i < 4; ++i) {
    codec::Ping ping;
    watcher->send_message(ping);
    watcher->pump_for(1s);
  }
  std::cout << "the squatter's room closed after " << gone_after << " s; the watcher read " << watcher_bytes
            << " bytes and is " << (watcher->closed() ? "gone" : "still there") << "\n";
  EXPECT_TRUE(squatted_room_gone) << "a room whose only person neither sends nor reads is freed";
  EXPECT_FALSE(watcher->closed()) << "a quiet watcher who reads stays";
  EXPECT_FALSE(watcher->closing.has_value()) << outcome(*watcher);
  EXPECT_NE(rooms_listed(server.http_port(), loopback(10, 1)).find("watched"), std::string::npos);
  EXPECT_GE(refusals(server.http_port(), "idle_person", loopback(10, 1)), 1);
}

// --- a crowd at a port's cap --------------------------------------------------

/// A server with an HTTP and a TCP port, started under `ulimit -n
/// descriptors`: each port then holds (descriptors - 64) / 2 connections.
class ServerWithDescriptors {
 public:
  ServerWithDescriptors(int descriptors, const std::string& extra_args)
      : data_(std::filesystem::temp_directory_path() / ("fw-shares-test-" + std::to_string(::getpid()) + "-" +
                                                         std::to_string(counter_++))),
        process_("/bin/sh -c 'ulimit -n " + std::to_string(descriptors) + " && exec \"$0\" \"$@\"' " +
                     test::bin("facewire-server"),
                 "--tcp 127.0.0.1:0 --data " + data_.string() + " " + extra_args) {
    const std::string line = process_.next_stdout_line(30000);
    const auto colon = line.rfind(':');
    if (colon != std::string::npos) tcp_port_ = std::atoi(line.c_str() + colon + 1);
  }
  ~ServerWithDescriptors() { std::filesystem::remove_all(data_); }
  int http_port() const { return process_.port(); }
  int tcp_port() const { return tcp_port_; }
  int port(Transport t) const { return t == Transport::tcp ? tcp_port_ : http_port(); }

 private:
  static inline int counter_ = 0;
  std::filesystem::path data_;
  test::ServerProcess process_;
  int tcp_port_ = 0;
};

/// 192 descriptors: 64 connections on each of the two ports.
constexpr int kDescriptors = 192;

/// Connections from many addresses that each hold a place the cheap way:
/// an HTTP request header that never ends, or a TCP connection that never
/// says hello. A connection the server closes is opened again at once, as
/// an attacker would. Records the refusals the crowd was sent.
class Crowd {
 public:
  /// `blocks` /24s of `hosts` addresses each, `per_address` connections from each.
  Crowd(int port, bool http, int first_block, int blocks, int hosts, int per_address)
      : port_(port), http_(http) {
    for (int b = 0; b < blocks; ++b)
      for (int h = 1; h <= hosts; ++h)
        for (int i = 0; i < per_address; ++i) members_.push_back({loopback(first_block + b, h), -1, {}, ""});
    for (auto& m : members_) open(m);
    thread_ = std::thread([this] { run(); });
  }
  ~Crowd() {
    stop_ = true;
    thread_.join();
    for (auto& m : members_)
      if (m.fd >= 0) ::close(m.fd);
  }

  struct Refusal {
    Clock::time_point at;
    std::string text;
  };
  std::vector<Refusal> refusals() const {
    std::lock_guard lock(mutex_);
    return refusals_;
  }
  /// When the first connection still open now was opened.
  Clock::time_point earliest_open() const {
    std::lock_guard lock(mutex_);
    auto earliest = Clock::time_point::max();
    for (const auto& m : members_)
      if (m.fd >= 0 && m.answer.empty()) earliest = std::min(earliest, m.opened);
    return earliest;
  }

 private:
  struct Member {
    std::string from;
    int fd;
    Clock::time_point opened;
    std::string answer;
  };
  void open(Member& m) {
    m.fd = connect_from(m.from, port_);
    m.opened = Clock::now();
    m.answer.clear();
    if (m.fd >= 0 && http_) send_text(m.fd, "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ");
  }
  void run() {
    while (!stop_) {
      {
        std::lock_guard lock(mutex_);
        for (auto& m : members_) {
          if (m.fd < 0) {
            open(m);
            continue;
          }
          const Received r = receive_for(m.fd, 0ms);
          m.answer += r.bytes;
          if (!r.closed) continue;
          if (!m.answer.empty()) refusals_.push_back({Clock::now(), m.answer});
          ::close(m.fd);
          open(m);  // at once, as an attacker would
        }
      }
      std::this_thread::sleep_for(50ms);
    }
  }

  int port_;
  bool http_;
  std::vector<Member> members_;
  std::vector<Refusal> refusals_;
  mutable std::mutex mutex_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// The seconds a refusal says to wait: Retry-After on HTTP, "try again in N s" in a closing message.
int retry_seconds(const std::string& answer) {
  if (const auto at = answer.find("Retry-After: "); at != std::string::npos) return std::atoi(answer.c_str() + at + 13);
  if (const auto at = answer.find("try again in "); at != std::string::npos) return std::atoi(answer.c_str() + at + 13);
  return -1;
}

// The measured attack: half-sent requests from 42 addresses held the HTTP
// port's 2,048 connections for the 10 s header deadline, in waves, and
// the refusal said "try again in a minute". Here 64 places on the port
// (an open-files limit of 192) and 42 addresses in three /24s: the crowd is
// refused, a person on a fresh address is served.
TEST(FairShares, HalfSentRequestsAtThePortsCapDoNotStopAPersonOnAFreshAddress) {
  ServerWithDescriptors server(kDescriptors, "--no-demo-room");
  ASSERT_GT(server.http_port(), 0);
  Crowd crowd(server.http_port(), true, 11, 3, 14, 5);  // 210 half-sent requests, more than the descriptors
  std::this_thread::sleep_for(2s);
  const auto first_refusals = crowd.refusals();
  ASSERT_FALSE(first_refusals.empty()) << "the crowd is refused past the port's places";

  int served = 0, joined = 0;
  std::string failures;
  for (int i = 0; i < 5; ++i) {
    const auto [status, text] = get_from(loopback(40, 1 + i), server.http_port(), "/healthz");
    if (status == 200) ++served;
    else failures += "healthz " + std::to_string(status) + ": " + text.substr(0, 200) + "\n";
    auto person = join_from(server, Transport::websocket, loopback(40, 1 + i), "person" + std::to_string(i));
    if (person->welcome) ++joined;
    else failures += "join: " + outcome(*person) + "\n";
    std::this_thread::sleep_for(1s);
  }
  const auto refused = crowd.refusals();
  std::cout << "210 half-sent requests from 42 addresses at a port of 64: " << refused.size()
            << " refused in 7 s; a person on a fresh address: /healthz 200 " << served << " of 5, joined " << joined
            << " of 5\n"
            << (failures.empty() ? "" : failures) << "first refusal: " << first_refusals.front().text << "\n";
  EXPECT_EQ(served, 5) << failures;
  EXPECT_EQ(joined, 5) << failures;
  const std::string& answer = first_refusals.front().text;
  EXPECT_TRUE(answer.rfind("HTTP/1.1 503 ", 0) == 0 || answer.rfind("HTTP/1.1 429 ", 0) == 0) << answer;
  EXPECT_GT(refusals(server.http_port(), "connection_evicted", loopback(41, 1)), 0)
      << "the person took the place of a connection that waited";
}

// The refusal's wait is the real one: the earliest header deadline (10 s
// from accept) of the connections that hold the places, not a fixed minute.
TEST(FairShares, TheCrowdIsToldTheRealWait) {
  ServerWithDescriptors server(128, "--no-demo-room");  // 32 places a port
  ASSERT_GT(server.http_port(), 0);
  const auto start = Clock::now();
  Crowd crowd(server.http_port(), true, 12, 1, 20, 6);  // 120 half-sent requests from one /24
  std::this_thread::sleep_for(1500ms);
  const auto refused = crowd.refusals();
  ASSERT_FALSE(refused.empty());
  // The first connections were accepted just after `start`: the first place
  // frees 10 s after that (the header deadline).
  for (const auto& refusal : refused) {
    const int said = retry_seconds(refusal.text);
    const double real = 10.0 - std::chrono::duration<double>(refusal.at - start).count();
    EXPECT_NEAR(said, real, 2.0) << refusal.text;
  }
  std::cout << refused.size() << " refused; the first told to wait " << retry_seconds(refused.front().text)
            << " s, for a place that frees in "
            << 10.0 - std::chrono::duration<double>(refused.front().at - start).count() << " s\n";
}

// The measured attack: with `ulimit -n 1024`, 1,100 silent TCP connections
// from 22 addresses refused every port for 8-10 s. Here 220 silent TCP
// connections from 22 addresses in two /24s, against 64 places a port (an
// open-files limit of 192): a person on a fresh address joins over TCP and
// gets /healthz on the HTTP port, the crowd is told to wait for the hello
// deadline (5 s) in a closing message.
TEST(FairShares, SilentTcpConnectionsAtThePortsCapDoNotStopAPersonJoining) {
  ServerWithDescriptors server(kDescriptors, "--no-demo-room");
  ASSERT_GT(server.tcp_port(), 0);
  const auto start = Clock::now();
  Crowd crowd(server.tcp_port(), false, 13, 2, 11, 10);  // 220 silent connections from 22 addresses
  std::this_thread::sleep_for(1500ms);
  int joined = 0, served = 0;
  std::string failures;
  for (int i = 0; i < 3; ++i) {
    auto person = join_from(server, Transport::tcp, loopback(40, 10 + i), "tcp-person" + std::to_string(i));
    if (person->welcome) ++joined;
    else failures += outcome(*person) + "\n";
    const auto [status, text] = get_from(loopback(40, 10 + i), server.http_port(), "/healthz");
    if (status == 200) ++served;
    else failures += "healthz " + std::to_string(status) + ": " + text.substr(0, 200) + "\n";
  }
  const auto refused = crowd.refusals();
  ASSERT_FALSE(refused.empty());
  std::cout << "220 silent TCP connections at a port of 64: a person joined " << joined << " of 3 and got /healthz "
            << served << " of 3; "
            << refused.size() << " refusals, the first after "
            << std::chrono::duration<double>(refused.front().at - start).count() << " s\n";
  EXPECT_EQ(joined, 3) << failures;
  EXPECT_EQ(served, 3) << failures;
  const std::string& first = refused.front().text;
  EXPECT_NE(first.find("try again in"), std::string::npos) << first;
  const double real = 5.0 - std::chrono::duration<double>(refused.front().at - start).count();
  EXPECT_NEAR(retry_seconds(first), real, 2.0) << first;
}

}  // namespace
}  // namespace fw::server
