// Limits per address and per room on the real server over loopback sockets
// (server/PROTOCOL.md, "Limits"): one address floods joins and chat while
// observers on other addresses keep their budget and their connection;
// joins over the rate are refused across reconnects; one address cannot
// take the rooms or fill the lobby. 127.0.0.1 is the attacker, 127.0.0.2
// and up the others (each client binds its address before connecting).
#include <atomic>
#include <chrono>
#include <iostream>
#include <thread>

#include <gtest/gtest.h>

#include "room_test_client.hpp"
#include "room_test_server.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;
using codec::CloseCode;

/// A client from `from` that said hello and got its welcome or closing message.
std::unique_ptr<RoomTestClient> join_from(const RunningServer& server, const std::string& from,
                                          const std::string& room, const std::string& name,
                                          std::uint32_t max_bps = 0, Transport transport = Transport::tcp) {
  auto client = std::make_unique<RoomTestClient>(transport, server.port(transport), from);
  EXPECT_TRUE(client->connected()) << "from " << from;
  client->hello(room, name, "", max_bps);
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 5s);
  return client;
}

std::string reason(const RoomTestClient& client) {
  return client.closing ? client.closing->reason : client.welcome ? "welcomed" : "no answer";
}

/// What the flood loop managed.
struct Flood {
  std::atomic<int> joins{0}, refused{0}, lines{0};
};

/// For `duration`, from 127.0.0.1: join, say five lines, leave; again.
void flood(const RunningServer& server, const std::string& room, std::chrono::milliseconds duration, Flood& done) {
  const auto end = std::chrono::steady_clock::now() + duration;
  for (int i = 0; std::chrono::steady_clock::now() < end; ++i) {
    RoomTestClient client(Transport::tcp, server.tcp_port(), "127.0.0.1");
    client.hello(room, "Flood" + std::to_string(i % 100));
    client.pump_until([&] { return client.welcome.has_value() || client.closing.has_value(); }, 2s);
    if (!client.welcome) {
      ++done.refused;
      continue;
    }
    ++done.joins;
    for (int line = 0; line < 5; ++line) client.send_message(codec::Chat{0, "flood line " + std::to_string(line)});
    done.lines += 5;
  }
}

// Before: 18,401 joins and 92,005 chat lines in 5 s from one address, and a
// client that asked for 9.6 kbit/s was sent 7 Mbit/s; a reading browser
// client was cut off for "not reading".
TEST(AddressRateLimits, AJoinAndChatFloodFromOneAddressLeavesObserversTheirBudget) {
  RunningServer server("--no-demo-room");
  constexpr std::uint32_t kBudget = 9600;
  auto host = join_from(server, "127.0.0.3", "flooded", "Host");
  auto thin = join_from(server, "127.0.0.2", "flooded", "Thin", kBudget);
  auto browser = join_from(server, "127.0.0.4", "flooded", "Browser", 0, Transport::websocket);
  ASSERT_TRUE(host->welcome && thin->welcome && browser->welcome) << reason(*thin) << "; " << reason(*browser);
  thin->pump_for(2s);  // the welcome and the host's preview behind it

  constexpr auto kWindow = 5s;
  Flood done;
  std::thread attacker([&] { flood(server, "flooded", kWindow, done); });
  const std::uint64_t bytes_before = thin->socket_bytes;
  const std::size_t chat_before = thin->chat.size(), presence_before = thin->presence.size();
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < kWindow) {
    thin->pump_for(50ms);
    browser->pump_for(50ms);
    host->pump_for(10ms);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  attacker.join();
  const double thin_bps = static_cast<double>(thin->socket_bytes - bytes_before) * 8 / seconds;
  std::cout << "flood from one address in " << seconds << " s: " << done.joins << " joins admitted, " << done.refused
            << " refused, " << done.lines << " chat lines sent; the 9.6 kbit/s observer got " << thin_bps
            << " bit/s, " << thin->chat.size() - chat_before << " chat lines, "
            << thin->presence.size() - presence_before << " presence messages" << std::endl;

  EXPECT_LE(done.joins, 20 + 7) << "a burst of 20, then one a second";
  EXPECT_GT(done.refused, 0);
  EXPECT_LE(thin_bps, kBudget * 1.1) << "the flood goes through the observer's budget";
  EXPECT_FALSE(thin->closed()) << reason(*thin);
  EXPECT_FALSE(browser->closed()) << "a reading client is not cut off: " << reason(*browser);
  EXPECT_TRUE(thin->errors.empty()) << thin->errors.front();
  EXPECT_LE(browser->chat.size(), 10u + 12u) << "a burst of 10 lines, then two a second";
  // And the faces still move for who reads.
  const auto frames = browser->room_frames;
  browser->pump_for(1s);
  EXPECT_GT(browser->room_frames, frames);
}

TEST(AddressRateLimits, JoinsOverTheRateAreRefusedAcrossReconnects) {
  RunningServer server("--no-demo-room");
  auto host = join_from(server, "127.0.0.3", "busy", "Host");  // keeps the room open
  ASSERT_TRUE(host->welcome);
  for (int i = 0; i < 20; ++i) {  // the burst: twenty hellos, each on a new connection
    auto client = join_from(server, "127.0.0.1", "busy", "Again");
    ASSERT_TRUE(client->welcome) << i << ": " << reason(*client);
  }
  auto over = join_from(server, "127.0.0.1", "busy", "Again");
  ASSERT_TRUE(over->closing) << reason(*over);
  EXPECT_EQ(over->closing->code, CloseCode::rate_limited);
  EXPECT_NE(over->closing->reason.find("too many joins from your address; try again in"), std::string::npos)
      << over->closing->reason;
  auto other = join_from(server, "127.0.0.2", "busy", "Other");
  EXPECT_TRUE(other->welcome) << "another address joins: " << reason(*other);
  std::this_thread::sleep_for(1200ms);  // one a second
  EXPECT_TRUE(join_from(server, "127.0.0.1", "busy", "Later")->welcome);
}

// Before: 999 idle joins took all 1000 rooms, and 12 joins filled the lobby.
TEST(AddressRateLimits, OneAddressCannotTakeTheRoomsOrFillTheLobby) {
  RunningServer server;  // the demo lobby: 16 seats, three taken by its own avatars
  std::vector<std::unique_ptr<RoomTestClient>> held;
  for (int i = 1; i <= 5; ++i) {
    held.push_back(join_from(server, "127.0.0.1", "squat" + std::to_string(i), "Squatter"));
    ASSERT_TRUE(held.back()->welcome) << i << ": " << reason(*held.back());
  }
  auto sixth = join_from(server, "127.0.0.1", "squat6", "Squatter");
  ASSERT_TRUE(sixth->closing) << reason(*sixth);
  EXPECT_EQ(sixth->closing->code, CloseCode::rate_limited);
  EXPECT_NE(sixth->closing->reason.find("too many new rooms"), std::string::npos) << sixth->closing->reason;
  EXPECT_TRUE(join_from(server, "127.0.0.2", "squat6", "Other")->welcome) << "another address opens a room";

  for (int i = 0; i < 8; ++i) {  // half the lobby's 16 seats
    held.push_back(join_from(server, "127.0.0.1", "lobby", "Squatter"));
    ASSERT_TRUE(held.back()->welcome) << i << ": " << reason(*held.back());
  }
  auto ninth = join_from(server, "127.0.0.1", "lobby", "Squatter");
  ASSERT_TRUE(ninth->closing) << reason(*ninth);
  EXPECT_EQ(ninth->closing->code, CloseCode::room_full);
  EXPECT_NE(ninth->closing->reason.find("from your address"), std::string::npos) << ninth->closing->reason;
  auto other = join_from(server, "127.0.0.2", "lobby", "Other");
  EXPECT_TRUE(other->welcome) << "another address still joins the lobby: " << reason(*other);
}

}  // namespace
}  // namespace fw::server
