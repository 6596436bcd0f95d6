#include "fw/codec/codec.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

// visible_error.cpp: what a viewer just misses, per channel.
TEST(VisibleError, IsAVertexErrorOfAThirdOfAMillimetreAndAGazeErrorUnderHalfADegree) {
  const auto e = default_visible_error();
  const double deg = 3.14159265358979 / 180;
  EXPECT_NEAR(e[au_channel(27, AuSide::both)] * 50.0, 0.35, 1e-6) << "AU 27 moves the chin 50 mm";
  EXPECT_NEAR(e[au_channel(12, AuSide::left)] * 9.5, 0.35, 1e-6);
  EXPECT_EQ(e[au_channel(12, AuSide::left)], e[au_channel(12, AuSide::right)]);
  EXPECT_NEAR(e[29] * 126.0, 0.35, 1e-6) << "head rotation at the farthest vertex";
  EXPECT_NEAR(e[32], 0.35, 1e-6);
  EXPECT_NEAR(e[35] / deg, 0.4, 1e-6);
  EXPECT_NEAR(e[39] * 10.0, 0.35, 1e-6);
  EXPECT_NEAR(e[46], 1.0 / 32, 1e-9);
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    EXPECT_GT(e[c], 0.0f) << channel_table()[c].name;
    EXPECT_GE(e[c], channel_table()[c].step) << channel_table()[c].name << ": the grid is finer than what is visible";
  }
}

TEST(VisibleError, LevelThreeIsTheVisibleOne) {
  EXPECT_EQ(kLevelFactor[3], 1.0);
  for (int l = 1; l <= kMaxQualityLevel; ++l) EXPECT_GT(kLevelFactor[static_cast<std::size_t>(l)], kLevelFactor[static_cast<std::size_t>(l - 1)]);
  EXPECT_LE(EncoderOptions{}.max_gaze_error_rad * 180 / 3.14159265, 0.4501);
}

}  // namespace
}  // namespace fw::codec
