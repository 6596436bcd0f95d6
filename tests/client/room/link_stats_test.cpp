#include "link_stats.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

using Clock = LinkStats::Clock;

TEST(LinkStats, SummaryHasTheAgreedKeysAndRates) {
  const auto start = Clock::time_point{} + std::chrono::hours(1);
  LinkStats stats(start);
  stats.bytes_down(1000);
  stats.bytes_up(250);
  stats.frame(3, "ada");
  stats.frame(3, "ada");
  stats.frame(7, "bo");
  for (int i = 1; i <= 100; ++i) stats.latency_ms(i);
  const auto json = stats.summary(start + std::chrono::seconds(2));
  EXPECT_EQ(json.at("avatars_seen"), 2);
  EXPECT_EQ(json.at("bytes_down"), 1000);
  EXPECT_DOUBLE_EQ(json.at("kbps_down").get<double>(), 4.0);  // 8000 bits in 2 s
  EXPECT_DOUBLE_EQ(json.at("kbps_up").get<double>(), 1.0);
  EXPECT_EQ(json.at("frames_per_avatar").at("ada"), 2);
  EXPECT_EQ(json.at("frames_per_avatar").at("bo"), 1);
  EXPECT_DOUBLE_EQ(json.at("latency_ms_p50").get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(json.at("latency_ms_p99").get<double>(), 99.0);
}

TEST(LinkStats, PerAvatarDetailsCountFromTheWelcome) {
  const auto start = Clock::now();
  LinkStats stats(start - std::chrono::seconds(5));
  stats.joined(start);
  stats.package(4, false, start + std::chrono::seconds(2));
  EXPECT_EQ(stats.avatars_seen(), 0u) << "a package alone is not a seen avatar";
  stats.frame(4, "kim");
  stats.package(4, true, start + std::chrono::seconds(9));
  stats.package(4, false, start + std::chrono::seconds(10));  // a late preview changes nothing
  const auto json = stats.summary(Clock::now());
  const auto& kim = json.at("avatars").at("kim");
  EXPECT_EQ(kim.at("frames"), 1);
  EXPECT_DOUBLE_EQ(kim.at("preview_s").get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(kim.at("full_s").get<double>(), 9.0);
  EXPECT_LT(kim.at("first_frame_s").get<double>(), 1.0);
  EXPECT_EQ(json.at("avatars_seen"), 1);
}

TEST(LinkStats, NoLatencyIsNullAndTwinNamesStayApart) {
  LinkStats stats;
  stats.frame(1, "sam");
  stats.frame(2, "sam");
  const auto json = stats.summary(Clock::now());
  EXPECT_TRUE(json.at("latency_ms_p50").is_null());
  EXPECT_EQ(json.at("frames_per_avatar").size(), 2u);
  EXPECT_TRUE(json.at("frames_per_avatar").contains("sam #2"));
}

TEST(LinkStats, KeepsABoundedSampleOfLatencies) {
  LinkStats stats;
  for (std::size_t i = 0; i < LinkStats::kMaxLatencySamples * 2; ++i) stats.latency_ms(i % 2 ? 10.0 : 20.0);
  const double p50 = stats.latency_percentile_ms(50);
  EXPECT_TRUE(p50 == 10.0 || p50 == 20.0);
  EXPECT_EQ(stats.summary(Clock::now()).at("latency_samples"), LinkStats::kMaxLatencySamples * 2);
}

TEST(LinkStats, RecentFrameRateCountsOnlyTheLastTenSeconds) {
  LinkStats stats;
  for (int i = 0; i < 5; ++i) stats.frame(1, "ada");
  const auto soon = stats.summary(Clock::now() + std::chrono::seconds(5)).at("avatars").at("ada");
  EXPECT_NEAR(soon.at("fps_recent").get<double>(), 1.0, 0.01);  // 5 frames in its 5 s of life
  const auto later = stats.summary(Clock::now() + std::chrono::seconds(20)).at("avatars").at("ada");
  EXPECT_EQ(later.at("fps_recent").get<double>(), 0.0);  // nothing in the last 10 s
  EXPECT_GT(later.at("fps").get<double>(), 0.2);         // though its whole life saw frames
}

TEST(LinkStats, LiveLineReportsTheLastInterval) {
  const auto start = Clock::now();
  LinkStats stats(start);
  stats.bytes_down(500);
  const std::string line = stats.live_line(start + std::chrono::seconds(1));
  EXPECT_NE(line.find("down 4.00 kbit/s"), std::string::npos) << line;
  stats.bytes_down(125);
  EXPECT_NE(stats.live_line(start + std::chrono::seconds(2)).find("down 1.00 kbit/s"), std::string::npos);
}

}  // namespace
}  // namespace fw::client
