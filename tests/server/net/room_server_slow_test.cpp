// The room server's limits that take seconds to show: the handshake
// time-out, a client that never reads, a client on a 9.6 kbit/s budget.
#include <gtest/gtest.h>

#include "http_get.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::join;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;

TEST(RoomServerLimits, SilenceBeforeHelloTimesOut) {
  RunningServer server("--no-demo-room");
  RoomTestClient client(Transport::tcp, server.tcp_port());
  const auto start = std::chrono::steady_clock::now();
  client.pump_until([&] { return client.closed(); }, 10s);
  ASSERT_TRUE(client.closing);
  EXPECT_EQ(client.closing->code, codec::CloseCode::handshake_timeout);
  EXPECT_GE(std::chrono::steady_clock::now() - start, 4s);
}

/// Ticks per second the room advanced, from the reader's timed room frames
/// that arrived after `since`.
double tick_rate(const RoomTestClient& reader, std::chrono::steady_clock::time_point since) {
  const auto first = std::find_if(reader.ticks.begin(), reader.ticks.end(), [&](const auto& t) { return t.first >= since; });
  if (first == reader.ticks.end() || first == reader.ticks.end() - 1) return 0;
  const auto& last = reader.ticks.back();
  return (last.second - first->second) / std::chrono::duration<double>(last.first - first->first).count();
}

TEST(RoomServerLimits, AClientThatNeverReadsCostsBoundedMemoryAndNobodyElsesFrames) {
  RunningServer server("--no-demo-room --max-client-bps 2000000");
  auto reader = std::make_unique<RoomTestClient>(Transport::websocket, server.http_port());
  reader->hello("busy", "Reader", "", 64000, /*timestamps=*/true);
  std::vector<std::unique_ptr<RoomTestClient>> others;
  for (int i = 0; i < 5; ++i) others.push_back(join(server, Transport::tcp, "busy", "Other" + std::to_string(i)));
  const auto pump_everyone = [&](std::chrono::milliseconds duration) {
    const auto end = std::chrono::steady_clock::now() + duration;
    while (std::chrono::steady_clock::now() < end) {
      reader->pump_for(50ms);
      for (auto& other : others) other->pump_for(1ms);
    }
  };
  pump_everyone(3s);  // packages delivered, streams settled
  ASSERT_TRUE(reader->welcome);
  const auto baseline_start = std::chrono::steady_clock::now();
  pump_everyone(3s);
  const double baseline_rate = tick_rate(*reader, baseline_start);
  const long rss_before = server.rss_kb();

  // Joins with a tiny receive buffer, then never reads: the
  // packages of seven avatars and the chat below are far more than the
  // kernel buffers hold.
  RoomTestClient sink(Transport::tcp, server.tcp_port());
  sink.shrink_receive_buffer(4096);
  sink.hello("busy", "Sink", "", 64000);
  const auto stall_start = std::chrono::steady_clock::now();
  for (int i = 0; i < 10; ++i) {
    reader->send_message(codec::Chat{0, std::string(400, 'x')});
    pump_everyone(600ms);
  }
  const double stall_rate = tick_rate(*reader, stall_start);
  const long rss_after = server.rss_kb();
  std::cout << "room ticks per second seen by a reader: " << baseline_rate << " before, " << stall_rate
            << " while a client does not read; server RSS " << rss_before << " -> " << rss_after << " kB\n";
  // The room keeps the pace it had before the sink came: 30 Hz on a quiet
  // machine; on a loaded one (other tests at once), the pace it had then.
  EXPECT_GT(stall_rate, std::min(27.0, 0.9 * baseline_rate)) << "the room keeps its pace";
  EXPECT_GT(stall_rate, 15.0) << "the room fell far behind its 30 Hz";
  ASSERT_TRUE(reader->link);
  EXPECT_EQ(reader->link->skipped_ticks, 0u) << "the reader misses nothing";
  EXPECT_FALSE(reader->closed());
  EXPECT_LT(rss_after - rss_before, 16 * 1024) << "memory stays bounded";
  const auto metrics = test::http_get(server.http_port(), "/metrics");
  EXPECT_EQ(metrics.body.find("facewire_dropped_ticks_total 0\n"), std::string::npos) << "the sink's ticks were skipped";
}

TEST(RoomServerLimits, ASlowClientsStreamStaysUnderItsBudgetAndShowsEveryFaceSoon) {
  RunningServer server;
  std::vector<std::unique_ptr<RoomTestClient>> others;
  for (int i = 0; i < 4; ++i)
    others.push_back(join(server, Transport::tcp, "lobby", "Other" + std::to_string(i), "", 200000));
  auto slow = join(server, Transport::tcp, "lobby", "Slow", "", 9600);
  ASSERT_TRUE(slow->welcome);
  ASSERT_EQ(slow->welcome->avatars.size(), 8u);
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // Bytes on the socket, length prefixes included, per measured second.
  std::vector<double> bits_per_second;
  double previews_done_at = 0;
  std::map<std::uint32_t, std::uint64_t> frames_at_20s;
  const std::uint64_t bytes_at_start = slow->socket_bytes;
  std::uint64_t bytes_at_2s = 0;
  while (seconds_since_start() < 40) {
    const auto window_start = std::chrono::steady_clock::now();
    const auto bytes_before = slow->socket_bytes;
    while (std::chrono::steady_clock::now() - window_start < 1s) {
      slow->pump_for(20ms);
      for (auto& other : others) other->pump_for(1ms);
    }
    const double window = std::chrono::duration<double>(std::chrono::steady_clock::now() - window_start).count();
    bits_per_second.push_back(static_cast<double>(slow->socket_bytes - bytes_before) * 8 / window);
    if (bits_per_second.size() == 2) bytes_at_2s = slow->socket_bytes;
    if (bits_per_second.size() == 20) frames_at_20s = slow->frames_per_avatar;
    std::size_t previews = 0;
    for (const auto& [key, package] : slow->packages) previews += key.second == 0 && package.complete();
    if (previews == 8 && previews_done_at == 0) previews_done_at = seconds_since_start();
  }
  const double mean_bps = static_cast<double>(slow->socket_bytes - bytes_at_2s) * 8 / (seconds_since_start() - 2);
  std::cout << "bit/s at a budget of 9600:";
  for (const double b : bits_per_second) std::cout << " " << static_cast<int>(b);
  std::cout << "\nmean after the first 2 s: " << mean_bps << "; frames per avatar per second in the last 20 s:";
  for (const auto& [id, count] : slow->frames_per_avatar)
    std::cout << " " << id << ":" << static_cast<double>(count - frames_at_20s[id]) / 20;
  std::cout << "\nall previews after " << previews_done_at << " s; room frame bytes " << slow->room_frame_bytes
            << ", package chunk bytes " << slow->package_bytes << " of " << slow->socket_bytes - bytes_at_start << "\n";
  // The first seconds carry the welcome and the codec's 594-byte stream header.
  EXPECT_LE(mean_bps, 9600);
  for (std::size_t s = 2; s < bits_per_second.size(); ++s)
    EXPECT_LE(bits_per_second[s], 9600 * 1.15) << "second " << s;
  EXPECT_GT(previews_done_at, 0) << "every preview arrives within 40 s";
  for (const auto& a : slow->welcome->avatars) EXPECT_GT(slow->frames_per_avatar[a.id], 0u) << a.name << " moves";
  EXPECT_TRUE(slow->errors.empty()) << slow->errors.front();
}

}  // namespace
}  // namespace fw::server
