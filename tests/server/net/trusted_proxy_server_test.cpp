// Clients behind a trusted proxy on the real server over loopback sockets
// (server/PROTOCOL.md, "Limits"): 127.0.0.1 plays the proxy, and the
// X-Forwarded-For it sends names the client that the per-address limits
// count (uploads, joins, connections); the same header from 127.0.0.2, a
// peer that is not trusted, counts for nothing. Without --trusted-proxy
// everything from the proxy shares one address's limits.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "http_get.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"
#include "run_command.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;

/// Sends `raw` from `source` (127.0.0.x) and reads the answer until the
/// server closes; status 0 if none came.
test::HttpReply exchange_from(const std::string& source, int port, const std::string& raw) {
  test::HttpReply reply;
  // 30 s: a loaded machine; an upload's answer comes from the photo worker.
  const int fd = test::connect_loopback_from(source.c_str(), port, 30);
  if (fd < 0) return reply;
  return test::http_exchange_on(fd, raw);
}

std::string forwarded_line(const std::string& x_forwarded_for) {
  return x_forwarded_for.empty() ? "" : "X-Forwarded-For: " + x_forwarded_for + "\r\n";
}

/// An upload's answer: the body is no photo, so an admitted upload is
/// answered 422 once the photo worker has looked at it; one over its
/// address's rate is answered 429 from its header.
int upload_status(const RunningServer& server, const std::string& from, const std::string& x_forwarded_for) {
  const std::string body(16, 'x');
  return exchange_from(from, server.http_port(),
                       "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\n" + forwarded_line(x_forwarded_for) +
                           "Content-Type: image/jpeg\r\nContent-Length: " + std::to_string(body.size()) +
                           "\r\nConnection: close\r\n\r\n" + body)
      .status;
}

test::HttpReply health_from(const RunningServer& server, const std::string& from, const std::string& x_forwarded_for) {
  return exchange_from(from, server.http_port(),
                       "GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n" + forwarded_line(x_forwarded_for) +
                           "Connection: close\r\n\r\n");
}

long refusals(const RunningServer& server, const std::string& kind) {
  const auto metrics = test::http_get(server.http_port(), "/metrics");
  std::smatch match;
  if (!std::regex_search(metrics.body, match, std::regex("facewire_refusals_total\\{kind=\"" + kind + "\"\\} (\\d+)")))
    return -1;
  return std::stol(match[1]);
}

/// Uploads from `from` naming `first` until its burst of 6 is spent, then
/// one naming `second`: that one's answer (422 admitted, 429 refused).
int upload_after_another_clients_burst(const RunningServer& server, const std::string& from, const std::string& first,
                                       const std::string& second) {
  for (int i = 0; i < 6; ++i) EXPECT_EQ(upload_status(server, from, first), 422) << "upload " << i << " for " << first;
  EXPECT_EQ(upload_status(server, from, first), 429) << first << "'s burst of 6 is spent";
  return upload_status(server, from, second);
}

constexpr const char* kSlowUploads = "--no-demo-room --uploads-per-minute 1";

// Before: with the flag, the second client behind the proxy was refused
// 429 like the first (every upload counted against 127.0.0.1).
TEST(TrustedProxy, UploadsThroughATrustedProxyCountAgainstEachClient) {
  RunningServer server(std::string(kSlowUploads) + " --trusted-proxy 127.0.0.1/32");
  ASSERT_GT(server.http_port(), 0);
  EXPECT_EQ(upload_after_another_clients_burst(server, "127.0.0.1", "203.0.113.1", "203.0.113.2"), 422)
      << "another client behind the proxy has its own rate";
  EXPECT_EQ(upload_status(server, "127.0.0.1", "198.51.100.9, 203.0.113.1"), 429)
      << "what the client writes left of the proxy's entry changes nothing";
  // The header from a peer that is not a trusted proxy is ignored: its
  // uploads share the peer's own rate, whatever they claim.
  EXPECT_EQ(upload_after_another_clients_burst(server, "127.0.0.2", "203.0.113.3", "203.0.113.4"), 429);
}

TEST(TrustedProxy, WithoutTheFlagEveryoneBehindTheProxySharesItsAddress) {
  RunningServer server(kSlowUploads);
  ASSERT_GT(server.http_port(), 0);
  EXPECT_EQ(upload_after_another_clients_burst(server, "127.0.0.1", "203.0.113.1", "203.0.113.2"), 429);
}

/// A WebSocket client from 127.0.0.1 that says it is `client`, welcomed or closed.
std::unique_ptr<RoomTestClient> join_as(const RunningServer& server, const std::string& client,
                                        const std::string& from = "127.0.0.1") {
  auto joined = std::make_unique<RoomTestClient>(Transport::websocket, server.http_port(), from, client);
  EXPECT_TRUE(joined->connected()) << client;
  joined->hello("proxied", "Guest");
  joined->pump_until([&] { return joined->welcome.has_value() || joined->closing.has_value(); }, 10s);
  return joined;
}

constexpr const char* kSlowJoins =
    "--no-demo-room --joins-per-minute 1 --room-size 64 --seats-per-address 64 --room-joins-per-minute 100000";

// Before: the second client behind the proxy was refused "too many joins
// from your address" once the first had spent the burst of 20.
TEST(TrustedProxy, JoinsThroughATrustedProxyCountAgainstEachClient) {
  RunningServer server(std::string(kSlowJoins) + " --trusted-proxy 127.0.0.1");
  ASSERT_GT(server.http_port(), 0);
  std::vector<std::unique_ptr<RoomTestClient>> seated;
  for (int i = 0; i < 20; ++i) {
    seated.push_back(join_as(server, "203.0.113.1"));
    ASSERT_TRUE(seated.back()->welcome) << "join " << i;
  }
  const auto over = join_as(server, "203.0.113.1");
  ASSERT_TRUE(over->closing) << "the client's burst of 20 is spent";
  EXPECT_EQ(over->closing->code, codec::CloseCode::rate_limited);
  EXPECT_TRUE(join_as(server, "203.0.113.2")->welcome) << "another client behind the proxy joins";
  // From an untrusted peer the header counts for nothing: its own address's burst.
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(join_as(server, "203.0.113.5", "127.0.0.2")->welcome) << i;
  EXPECT_TRUE(join_as(server, "203.0.113.6", "127.0.0.2")->closing);
}

TEST(TrustedProxy, WithoutTheFlagJoinsThroughTheProxyShareItsRate) {
  RunningServer server(kSlowJoins);
  ASSERT_GT(server.http_port(), 0);
  std::vector<std::unique_ptr<RoomTestClient>> seated;
  for (int i = 0; i < 20; ++i) {
    seated.push_back(join_as(server, "203.0.113.1"));
    ASSERT_TRUE(seated.back()->welcome) << "join " << i;
  }
  const auto other = join_as(server, "203.0.113.2");
  ASSERT_TRUE(other->closing);
  EXPECT_EQ(other->closing->code, codec::CloseCode::rate_limited);
}

// The per-address connection share (2 here) does not cut the proxy off:
// its connections count against the clients its requests name.
TEST(TrustedProxy, TheConnectionShareCountsClientsNotTheProxy) {
  RunningServer server("--no-demo-room --max-connections-per-address 2 --trusted-proxy 127.0.0.1");
  ASSERT_GT(server.http_port(), 0);
  std::vector<std::unique_ptr<RoomTestClient>> held;
  for (const char* client : {"203.0.113.1", "203.0.113.1", "203.0.113.2", "203.0.113.3", "203.0.113.4"}) {
    held.push_back(join_as(server, client));
    ASSERT_TRUE(held.back()->welcome) << client;
  }
  const auto third = health_from(server, "127.0.0.1", "203.0.113.1");
  EXPECT_EQ(third.status, 429) << "203.0.113.1 holds its two";
  EXPECT_NE(third.body.find("too many connections from your address"), std::string::npos) << third.body;
  EXPECT_NE(third.headers.find("Retry-After: "), std::string::npos) << third.headers;
  EXPECT_EQ(health_from(server, "127.0.0.1", "203.0.113.9").status, 200);
  EXPECT_GE(refusals(server, "address_connection_limit"), 1);
  held.erase(held.begin());  // one of 203.0.113.1's leaves
  bool admitted = false;     // once the server has seen it go
  for (int i = 0; i < 50 && !admitted; ++i, std::this_thread::sleep_for(100ms))
    admitted = health_from(server, "127.0.0.1", "203.0.113.1").status == 200;
  EXPECT_TRUE(admitted) << "a closed connection gives its client's place back";
}

TEST(TrustedProxy, WithoutTheFlagTheProxyHoldsOneAddresssShare) {
  RunningServer server("--no-demo-room --max-connections-per-address 2");
  ASSERT_GT(server.http_port(), 0);
  const auto first = join_as(server, "203.0.113.1");
  const auto second = join_as(server, "203.0.113.2");
  ASSERT_TRUE(first->welcome && second->welcome);
  EXPECT_EQ(health_from(server, "127.0.0.1", "203.0.113.3").status, 429);
}

// A header that names no address: the proxy's own address counts, and the
// refusal kind says so.
TEST(TrustedProxy, AMalformedHeaderFromTheProxyCountsAsTheProxyAndIsCounted) {
  RunningServer server(std::string(kSlowUploads) + " --trusted-proxy 127.0.0.1");
  ASSERT_GT(server.http_port(), 0);
  EXPECT_EQ(upload_after_another_clients_burst(server, "127.0.0.1", "not-an-address", "127.0.0.1"), 429)
      << "a malformed header's uploads were the proxy's own";
  EXPECT_EQ(upload_status(server, "127.0.0.1", "203.0.113.1"), 422) << "the clients behind it are not held up";
  EXPECT_EQ(refusals(server, "bad_forwarded_header"), 7);
}

TEST(TrustedProxy, TheEnvironmentAndTheConfigFileTakeRangesToo) {
  const auto share_taken = [](const RunningServer& server) {
    const auto held = join_as(server, "203.0.113.1");
    EXPECT_TRUE(held->welcome);
    return health_from(server, "127.0.0.1", "203.0.113.2").status == 429;
  };
  ::setenv("FACEWIRE_TRUSTED_PROXY", "10.0.0.0/8, 127.0.0.1", 1);
  {
    RunningServer server("--no-demo-room --max-connections-per-address 1");
    EXPECT_FALSE(share_taken(server)) << "FACEWIRE_TRUSTED_PROXY, comma-separated";
  }
  ::unsetenv("FACEWIRE_TRUSTED_PROXY");
  const auto config = std::filesystem::temp_directory_path() / ("fw-proxy-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(config) << "[serve]\ntrusted-proxy = [\"fd00::/8\", \"127.0.0.0/24\"]\n";
  {
    RunningServer server("--no-demo-room --max-connections-per-address 1 --config " + config.string());
    EXPECT_FALSE(share_taken(server)) << "trusted-proxy in the config file";
  }
  std::filesystem::remove(config);
  RunningServer untrusting("--no-demo-room --max-connections-per-address 1");
  EXPECT_TRUE(share_taken(untrusting)) << "the check itself";
}

TEST(TrustedProxy, ARangeThatIsNoneIsAUsageErrorThatSaysWhatToWrite) {
  const auto result = test::run_command(test::bin("facewire-server") + " serve --trusted-proxy 10.0.0.1/8");
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_NE(result.output.find("--trusted-proxy"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("10.0.0.0/8"), std::string::npos) << result.output;
  const auto word = test::run_command(test::bin("facewire-server") + " serve --trusted-proxy proxy.example");
  EXPECT_EQ(word.status, 2) << word.output;
  EXPECT_NE(word.output.find("ADDRESS/PREFIX"), std::string::npos) << word.output;
}

}  // namespace
}  // namespace fw::server
