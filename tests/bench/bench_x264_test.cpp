// facewire-bench codec's side-by-side with a video codec: it renders and
// codes video for half a minute, so it runs in its own executable, labelled
// slow (make test runs it; the quick and sanitizer passes do not).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.hpp"

namespace fw::bench {
namespace {

// The side-by-side with a video codec: the scene's first active avatar
// rendered as the astronaut, coded by x264 at our picture quality.
TEST(BenchCodecSlow, SetsX264AgainstOursAtTheSamePictureQuality) {
  const auto result = test::run_command(test::bin("facewire-bench") + " codec --json --seconds 4", false, 150);
  ASSERT_EQ(result.status, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << result.output;
  const auto& scene = json.at("scenes").at(0);
  const auto& x264 = scene.at("x264");
  ASSERT_FALSE(x264.contains("skipped")) << x264.dump();
  EXPECT_EQ(x264.at("frames").get<int>(), 4 * 30);
  EXPECT_GT(x264.at("ours_psnr_db").get<double>(), 20.0);
  EXPECT_TRUE(x264.at("x264_reached_our_psnr").get<bool>());
  EXPECT_GE(x264.at("x264_psnr_db").get<double>(), x264.at("ours_psnr_db").get<double>());
  EXPECT_GT(scene.at("x264_over_ours").get<double>(), 1.0);
}

}  // namespace
}  // namespace fw::bench
