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
}

TEST(BenchFanout, RefusesBadCounts) {
  const auto result = test::run_command(test::bin("facewire-bench") + " fanout --rooms 0 --json");
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.output.find("--rooms"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace fw::bench
