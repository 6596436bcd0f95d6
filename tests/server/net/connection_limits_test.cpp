// Connection limits, on the real server over loopback sockets: every
// connection counts against its address from accept to close (still
// sending its request, upgraded, greeting), a header or hello has a fixed
// deadline, running out of file descriptors neither spins nor floods the
// log, and WebSocket pings count as messages. Other loopback addresses
// (127.0.0.2, 127.0.0.3) stand in for other clients.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <gtest/gtest.h>

#include "fw/codec/messages.hpp"
#include "loopback_socket.hpp"
#include "room_inbox.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"
#include "run_command.hpp"
#include "server_process.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// --- raw sockets from a chosen loopback address ------------------------------

/// A blocking TCP connection from `source` to 127.0.0.1:`port`; -1 on failure.
int connect_from(const char* source, int port) { return test::connect_loopback_from(source, port, 0); }

using test::Received;
using test::receive_for;
using test::send_text;

/// A whole HTTP exchange from `source`: the status (0 if none came within `timeout`) and the text.
std::pair<int, std::string> http_from(const char* source, int port, const std::string& request,
                                      std::chrono::milliseconds timeout = 5s) {
  const int fd = connect_from(source, port);
  if (fd < 0) return {0, "cannot connect"};
  send_text(fd, request);
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

std::pair<int, std::string> get_from(const char* source, int port, const std::string& path,
                                     std::chrono::milliseconds timeout = 5s) {
  return http_from(source, port, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n",
                   timeout);
}

/// facewire_refusals_total{kind="`kind`"} in /metrics, asked from 127.0.0.3; -1 if absent.
long refusals(int port, const std::string& kind) {
  const auto [status, text] = get_from("127.0.0.3", port, "/metrics");
  const std::string key = "facewire_refusals_total{kind=\"" + kind + "\"} ";
  const auto at = text.find(key);
  if (status != 200 || at == std::string::npos) return -1;
  return std::atol(text.c_str() + at + key.size());
}

namespace net = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;

/// A WebSocket to the room protocol from `source` that can send what the
/// test client does not: control frames, text messages.
class RawWebSocket {
 public:
  RawWebSocket(int port, const char* source) {
    auto& socket = beast::get_lowest_layer(ws_).socket();
    beast::error_code ec;
    socket.open(net::ip::tcp::v4(), ec);
    if (!ec) socket.bind({net::ip::make_address(source), 0}, ec);
    if (!ec) socket.connect({net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)}, ec);
    if (!ec) ws_.handshake("127.0.0.1", "/ws", ec);
    ws_.binary(true);
    connected_ = !ec;
  }
  bool connected() const { return connected_; }
  websocket::stream<beast::tcp_stream>& stream() { return ws_; }

  template <class Message>
  void send_message(const Message& message) {
    std::vector<std::uint8_t> bytes;
    codec::write_message(message, bytes);
    beast::error_code ignored;
    ws_.write(net::buffer(bytes), ignored);
  }
  /// Reads and files messages until `done()`, the connection closes or
  /// `timeout` passes; true if it closed.
  template <class Predicate>
  bool pump_until(Predicate done, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (!closed_ && !done() && Clock::now() < deadline) {
      if (!reading_) {
        reading_ = true;
        ws_.async_read(buffer_, [this](beast::error_code ec, std::size_t) {
          read_done_ = true;
          read_failed_ = static_cast<bool>(ec);
        });
      }
      ioc_.restart();
      while (!read_done_ && Clock::now() < deadline) ioc_.run_one_for(deadline - Clock::now());
      if (!read_done_) break;
      read_done_ = reading_ = false;
      if (read_failed_) {
        closed_ = true;
        break;
      }
      const auto bytes = buffer_.cdata();
      const auto* begin = static_cast<const std::uint8_t*>(bytes.data());
      inbox.file({begin, begin + bytes.size()});
      buffer_.consume(buffer_.size());
    }
    return closed_;
  }

  test::RoomInbox inbox;

 private:
  net::io_context ioc_;
  websocket::stream<beast::tcp_stream> ws_{ioc_};
  beast::flat_buffer buffer_;
  bool connected_ = false, reading_ = false, read_done_ = false, read_failed_ = false, closed_ = false;
};

/// Seconds from connecting to a welcome, for a WebSocket client from `source`; -1 if none came within 10 s.
double seconds_to_join(int port, const char* source, const std::string& room, const std::string& name) {
  const auto start = Clock::now();
  RawWebSocket client(port, source);
  if (!client.connected()) return -1;
  codec::Hello hello;
  hello.room = room;
  hello.name = name;
  client.send_message(hello);
  client.pump_until([&] { return client.inbox.welcome.has_value(); }, 10s);
  return client.inbox.welcome ? seconds_since(start) : -1;
}

// --- slowloris -------------------------------------------------------------

/// Connections that each send a partial request and then one more byte a
/// second, the way a slowloris holds a server's connections; tells when the
/// server closed each.
class Dribblers {
 public:
  Dribblers(int port, int count) {
    for (int i = 0; i < count; ++i) {
      Dribbler d;
      d.opened = Clock::now();
      d.fd = connect_from("127.0.0.1", port);
      if (d.fd >= 0) send_text(d.fd, "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ");
      dribblers_.push_back(d);
    }
    thread_ = std::thread([this] { run(); });
  }
  ~Dribblers() {
    stop_ = true;
    thread_.join();
    for (auto& d : dribblers_)
      if (d.fd >= 0) ::close(d.fd);
  }

  /// Connections the server refused at once (an answer and a close within 2 s of connecting, not 10).
  int refused_at_once() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(std::count_if(dribblers_.begin(), dribblers_.end(), [](const Dribbler& d) {
      return d.closed_after >= 0 && d.closed_after < 2.0 && d.answer.find("too many connections") != std::string::npos;
    }));
  }
  int open() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(std::count_if(dribblers_.begin(), dribblers_.end(), [](const Dribbler& d) {
      return d.fd >= 0 && d.closed_after < 0;
    }));
  }
  /// The longest any connection the server took stayed open; -1 while one is still open.
  double longest_held() const {
    std::lock_guard lock(mutex_);
    double longest = 0;
    for (const auto& d : dribblers_) {
      if (d.closed_after < 0) return -1;
      longest = std::max(longest, d.closed_after);
    }
    return longest;
  }
  std::string first_answer() const {
    std::lock_guard lock(mutex_);
    for (const auto& d : dribblers_)
      if (!d.answer.empty()) return d.answer;
    return "";
  }

 private:
  struct Dribbler {
    int fd = -1;
    Clock::time_point opened;
    double closed_after = -1;  ///< seconds from connecting to the server's close
    std::string answer;
  };
  void run() {
    auto next_byte = Clock::now() + 1s;
    while (!stop_) {
      {
        std::lock_guard lock(mutex_);
        const bool dribble = Clock::now() >= next_byte;
        for (auto& d : dribblers_) {
          if (d.fd < 0 || d.closed_after >= 0) continue;
          const Received r = receive_for(d.fd, 0ms);
          d.answer += r.bytes;
          if (r.closed) d.closed_after = seconds_since(d.opened);
          else if (dribble) send_text(d.fd, "x");  // never the end of the header
        }
        if (dribble) next_byte += 1s;
      }
      std::this_thread::sleep_for(100ms);
    }
  }

  std::vector<Dribbler> dribblers_;
  mutable std::mutex mutex_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

TEST(ConnectionLimits, ASlowlorisFromOneAddressDoesNotStopAnotherJoiningAndIsLetGoAtTheDeadline) {
  RunningServer server("--no-demo-room --max-connections-per-address 32");
  ASSERT_GT(server.http_port(), 0);
  Dribblers slowloris(server.http_port(), 40);
  std::this_thread::sleep_for(1500ms);
  EXPECT_GE(slowloris.refused_at_once(), 40 - 32) << "past the address's share: " << slowloris.first_answer();
  EXPECT_LE(slowloris.open(), 32);

  const double join_seconds = seconds_to_join(server.http_port(), "127.0.0.2", "calm", "Visitor");
  const auto [health, health_text] = get_from("127.0.0.3", server.http_port(), "/healthz");
  std::cout << "while 40 connections dribble from 127.0.0.1: " << slowloris.refused_at_once()
            << " refused at once, a join from 127.0.0.2 took " << join_seconds << " s, /healthz answered " << health
            << "\n";
  EXPECT_GE(join_seconds, 0) << "another address joins";
  EXPECT_LT(join_seconds, 1.0) << "and within a second";
  EXPECT_EQ(health, 200) << health_text;

  // A byte a second does not extend the header's deadline (10 s from accept).
  const auto wait_start = Clock::now();
  while (slowloris.longest_held() < 0 && Clock::now() - wait_start < 20s) std::this_thread::sleep_for(200ms);
  const double held = slowloris.longest_held();
  std::cout << "the dribbling connections were let go " << held << " s after connecting\n";
  EXPECT_GE(held, 9.0);
  EXPECT_LT(held, 12.5) << "the header deadline is 10 s, however slowly bytes come";
  EXPECT_GT(refusals(server.http_port(), "address_connection_limit"), 0);
  EXPECT_GT(refusals(server.http_port(), "handshake_timeout"), 0);
}

// --- connections still greeting count ------------------------------------

TEST(ConnectionLimits, ConnectionsStillGreetingCountAgainstTheAddressUntilTheirHelloTimesOut) {
  RunningServer server("--no-demo-room --max-connections-per-address 8");
  ASSERT_GT(server.tcp_port(), 0);
  // Four TCP connections that never say hello, and four upgraded WebSockets
  // that never say hello: eight, on two ports, all counted.
  std::vector<int> silent;
  for (int i = 0; i < 4; ++i) silent.push_back(connect_from("127.0.0.1", server.tcp_port()));
  std::vector<std::unique_ptr<RoomTestClient>> upgraded;
  for (int i = 0; i < 4; ++i) {
    upgraded.push_back(std::make_unique<RoomTestClient>(Transport::websocket, server.http_port()));
    EXPECT_TRUE(upgraded.back()->connected());
  }
  const auto greeting_since = Clock::now();

  // The ninth, on either port, is refused at once, and says why.
  const int ninth_tcp = connect_from("127.0.0.1", server.tcp_port());
  const Received tcp_answer = receive_for(ninth_tcp, 2s);
  EXPECT_TRUE(tcp_answer.closed) << "the TCP port refuses the ninth";
  EXPECT_NE(tcp_answer.bytes.find("too many connections"), std::string::npos) << "in a closing message";
  ::close(ninth_tcp);
  const auto [ninth_http, ninth_text] = get_from("127.0.0.1", server.http_port(), "/healthz");
  EXPECT_EQ(ninth_http, 429) << ninth_text;
  // Another address is not affected.
  EXPECT_GE(seconds_to_join(server.http_port(), "127.0.0.2", "room", "Other"), 0);

  // The hello's deadline (5 s) lets them go, and their places with them.
  for (auto& client : upgraded) client->pump_until([&] { return client->closed(); }, 10s);
  for (const int fd : silent) receive_for(fd, 10s);
  const double let_go = seconds_since(greeting_since);
  for (auto& client : upgraded) {
    ASSERT_TRUE(client->closing);
    EXPECT_EQ(client->closing->code, codec::CloseCode::handshake_timeout);
  }
  for (const int fd : silent) ::close(fd);
  std::this_thread::sleep_for(200ms);
  const auto [after, after_text] = get_from("127.0.0.1", server.http_port(), "/healthz");
  std::cout << "eight greeting connections held the address's share for " << let_go << " s\n";
  EXPECT_EQ(after, 200) << after_text;
  RoomTestClient again(Transport::tcp, server.tcp_port());
  again.hello("room", "Again");
  EXPECT_TRUE(again.pump_until([&] { return again.welcome.has_value() || again.closed(); }, 5s));
  EXPECT_TRUE(again.welcome) << "the address has its places back";
  EXPECT_GE(refusals(server.http_port(), "address_connection_limit"), 2);
  EXPECT_GE(refusals(server.http_port(), "handshake_timeout"), 8);
}

// --- descriptors run out --------------------------------------------------

/// User and system CPU seconds of process `pid` so far.
double cpu_seconds(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  std::istringstream fields(text.substr(text.rfind(')') + 2));
  std::string field;
  double ticks = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i)
    if (i == 14 || i == 15) ticks += std::stod(field);  // utime, stime
  return ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

std::size_t lines_in(const std::filesystem::path& file) {
  std::ifstream in(file);
  return static_cast<std::size_t>(
      std::count(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), '\n'));
}

TEST(ConnectionLimits, RunningOutOfDescriptorsNeitherSpinsNorFloodsTheLogAndRefusesPolitely) {
  const auto data = std::filesystem::temp_directory_path() / ("fw-conn-test-" + std::to_string(::getpid()));
  const auto log = data.string() + ".log";
  // 128 descriptors for the server alone (the shell sets the limit, then
  // becomes the server); the per-address share is raised so that the
  // descriptors run out first.
  test::ServerProcess server(
      "/bin/sh -c 'ulimit -n 128 && exec \"$0\" \"$@\"' " + test::bin("facewire-server"),
      "--no-demo-room --max-connections-per-address 1000 --data " + data.string() + " 2> " + log);
  ASSERT_GT(server.port(), 0);
  const double cpu_before = cpu_seconds(server.pid());
  std::vector<int> silent;
  for (int i = 0; i < 200; ++i) silent.push_back(connect_from("127.0.0.1", server.port()));
  EXPECT_EQ(std::count(silent.begin(), silent.end(), -1), 0);

  // While the descriptors are taken, another address is told so at once.
  std::this_thread::sleep_for(1s);
  const auto [during, during_text] = get_from("127.0.0.2", server.port(), "/healthz", 3s);
  std::this_thread::sleep_for(2s);
  const double cpu = cpu_seconds(server.pid()) - cpu_before;
  const std::size_t log_lines = lines_in(log);
  int answered = 0;
  for (const int fd : silent)
    if (receive_for(fd, 0ms).bytes.find("503") != std::string::npos) ++answered;
  std::cout << "200 silent connections against 128 descriptors: " << cpu << " CPU-seconds in 3 s, " << log_lines
            << " log lines, " << answered << " told 503 at once; another address got " << during << "\n";
  EXPECT_LT(cpu, 0.5) << "accept() does not spin";
  EXPECT_LT(log_lines, 50u) << "nor the log explode";
  EXPECT_GT(answered, 0) << "the connections past the descriptors are refused, not left waiting";
  EXPECT_EQ(during, 503) << "another address is refused politely, not left hanging: " << during_text;

  for (const int fd : silent) ::close(fd);
  std::this_thread::sleep_for(500ms);
  const auto [after, after_text] = get_from("127.0.0.2", server.port(), "/healthz");
  EXPECT_EQ(after, 200) << "served again once the connections closed: " << after_text;
  // The port takes its part of the descriptors ((128 - 64) per port) and is
  // full before they run out: the refusals are the port's.
  EXPECT_GT(refusals(server.port(), "connection_limit") + refusals(server.port(), "descriptors_exhausted"), 0);
  std::filesystem::remove_all(data);
  std::filesystem::remove(log);
}

// --- WebSocket pings -------------------------------------------------------

TEST(ConnectionLimits, AWebSocketPingFloodIsClosedAsAnyMessageFloodAndTheRoomCarriesOn) {
  RunningServer server("--no-demo-room");
  auto calm = test::join(server, Transport::websocket, "pings", "Calm");
  ASSERT_TRUE(calm->welcome);

  RawWebSocket flood(server.http_port(), "127.0.0.2");
  ASSERT_TRUE(flood.connected());
  codec::Hello hello;
  hello.room = "pings";
  hello.name = "Flood";
  flood.send_message(hello);
  flood.pump_until([&] { return flood.inbox.welcome.has_value(); }, 5s);
  ASSERT_TRUE(flood.inbox.welcome);

  int pongs = 0;
  flood.stream().control_callback([&](websocket::frame_type kind, beast::string_view) {
    if (kind == websocket::frame_type::pong) ++pongs;
  });
  int sent = 0;
  for (beast::error_code ec; sent < 3000 && !ec; ++sent) flood.stream().ping({}, ec);
  const bool closed = flood.pump_until([] { return false; }, 10s);
  std::cout << "a client sent " << sent << " WebSocket pings as fast as it could; the server answered " << pongs
            << " and " << (closed ? "closed it" : "did not close it") << "\n";
  EXPECT_TRUE(closed);
  ASSERT_TRUE(flood.inbox.closing) << "the server says why";
  EXPECT_EQ(flood.inbox.closing->code, codec::CloseCode::rate_limited) << flood.inbox.closing->reason;
  EXPECT_LT(pongs, 1000) << "well before a thousand pings";

  // The other person in the room notices nothing.
  calm->send_message(codec::Ping{7, 0});
  EXPECT_TRUE(calm->pump_until([&] { return !calm->pongs.empty(); }, 5s));
  calm->pump_for(1s);
  EXPECT_FALSE(calm->closed());
  EXPECT_GT(refusals(server.http_port(), "message_rate"), 0);
}

// --- refusals are counted -----------------------------------------------------

TEST(ConnectionLimits, BadRequestsAndProtocolViolationsAreCountedInMetrics) {
  RunningServer server("--no-demo-room");
  EXPECT_EQ(get_from("127.0.0.2", server.http_port(), "/no-such-page").first, 404);
  EXPECT_EQ(http_from("127.0.0.2", server.http_port(), "NONSENSE\r\n\r\n").first, 400);
  // A text message on the room protocol's WebSocket.
  RawWebSocket text(server.http_port(), "127.0.0.2");
  ASSERT_TRUE(text.connected());
  text.stream().text(true);
  beast::error_code ignored;
  text.stream().write(net::buffer(std::string("hello?")), ignored);
  EXPECT_TRUE(text.pump_until([] { return false; }, 5s));
  // A length prefix that never ends on TCP.
  const int tcp = connect_from("127.0.0.2", server.tcp_port());
  send_text(tcp, std::string(8, '\xff'));
  EXPECT_TRUE(receive_for(tcp, 5s).closed);
  ::close(tcp);
  EXPECT_GE(refusals(server.http_port(), "http_bad_request"), 2);
  EXPECT_GE(refusals(server.http_port(), "protocol_violation"), 2);
}

}  // namespace
}  // namespace fw::server
