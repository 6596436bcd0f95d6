// facewire-bench fanout runs a real server and real WebSocket clients and
// prints the JSON the room-server issue asks for. Values are checked for
// sanity only: benchmarks measure, tests do not time.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.hpp"

namespace fw::bench {
namespace {

TEST(BenchFanout, PrintsOneJsonObjectWithTheAgreedKeys) {
  const auto result = test::run_command(
      test::bin("facewire-bench") + " fanout --rooms 2 --per-room 3 --seconds 1 --warmup 1 --json", false);
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_TRUE(json.is_object()) << result.output;
  EXPECT_EQ(json.at("clients"), 6);
  EXPECT_EQ(json.at("clients_held"), 6) << "every client stays connected";
  EXPECT_GT(json.at("avatar_frames_per_s").get<double>(), 0.0);
  EXPECT_GE(json.at("latency_ms_p99").get<double>(), json.at("latency_ms_p50").get<double>());
  EXPECT_GT(json.at("server_rss_mb").get<double>(), 1.0);
  EXPECT_GE(json.at("server_cpu_pct").get<double>(), 0.0);
  EXPECT_EQ(json.at("decode_errors"), 0);
  EXPECT_EQ(json.at("nodes"), 1) << "one process, no Redis, by default";
  EXPECT_EQ(json.at("redis_cpu_pct"), 0.0);
  EXPECT_GT(json.at("cpu_us_per_avatar_frame").get<double>(), 0.0);
  // Each face goes to the room's three streams (its own person's too) on
  // alike links: one encoder's frames serve all three.
  EXPECT_GT(json.at("shared_frame_share").get<double>(), 0.3);
  EXPECT_LE(json.at("shared_frame_share").get<double>(), 2.0 / 3.0 + 0.01);
}

// --nodes 1,2: one process, then a redis-server and two cluster nodes with
// every room's clients on both; the runs side by side and their ratio.
TEST(BenchFanout, RunsOneNodeAndATwoNodeClusterSideBySide) {
  if (test::run_command("command -v redis-server").status != 0)
    GTEST_SKIP() << "redis-server is not on PATH: install redis-server (deploy/install-deps.sh)";
  const auto result = test::run_command(
      test::bin("facewire-bench") + " fanout --rooms 2 --per-room 2 --seconds 1 --warmup 1 --nodes 1,2 --json", false);
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_TRUE(json.is_object()) << result.output;
  ASSERT_EQ(json.at("runs").size(), 2u) << result.output;
  const auto& one = json.at("runs").at(0);
  const auto& two = json.at("runs").at(1);
  EXPECT_EQ(one.at("nodes"), 1);
  EXPECT_EQ(one.at("per_node").size(), 1u);
  EXPECT_EQ(two.at("nodes"), 2);
  ASSERT_EQ(two.at("per_node").size(), 2u);
  int rooms_owned = 0;
  for (const auto& node : two.at("per_node")) {
    EXPECT_EQ(node.at("clients"), 2) << "each room has a client on each node";
    rooms_owned += node.at("rooms_owned").get<int>();
  }
  EXPECT_EQ(rooms_owned, 2) << "Redis names an owner for each room";
  EXPECT_EQ(two.at("clients_held"), 4) << "every client stays connected";
  EXPECT_GT(two.at("avatar_frames_per_s").get<double>(), 0.0) << "frames cross the nodes";
  EXPECT_EQ(two.at("decode_errors"), 0);
  EXPECT_GE(two.at("redis_cpu_pct").get<double>(), 0.0);
  EXPECT_GE(two.at("latency_from_owner_ms_p99").get<double>(), two.at("latency_from_owner_ms_p50").get<double>());
  EXPECT_GT(json.at("cpu_per_frame_ratio").get<double>(), 0.0);
}

TEST(BenchFanout, RefusesBadNodeCounts) {
  for (const char* nodes : {"0", "1,", "two", "1,99"}) {
    const auto result = test::run_command(test::bin("facewire-bench") + " fanout --nodes " + nodes + " --json");
    EXPECT_NE(result.status, 0) << nodes;
    EXPECT_NE(result.output.find("--nodes"), std::string::npos) << result.output;
  }
}

TEST(BenchFanout, RefusesBadCounts) {
  const auto result = test::run_command(test::bin("facewire-bench") + " fanout --rooms 0 --json");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("--rooms"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace fw::bench
