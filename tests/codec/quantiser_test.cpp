#include "quantiser.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "test_seed.hpp"

namespace fw::codec {
namespace {

TEST(Quantiser, ChannelValueReachesEveryField) {
  FaceParams p;
  for (std::size_t c = 0; c < kChannelCount; ++c) set_channel_value(p, c, static_cast<float>(c) + 0.5f);
  EXPECT_EQ(p.au[3], 3.5f);
  EXPECT_EQ(p.head_yaw_rad, 29.5f);
  EXPECT_EQ(p.head_translation_mm[2], 34.5f);
  EXPECT_EQ(p.eye_right.pitch_rad, 38.5f);
  EXPECT_EQ(p.lid_right, 40.5f);
  EXPECT_EQ(p.blush[2], 43.5f);
  EXPECT_EQ(p.pallor, 46.5f);
  for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_EQ(channel_value(p, c), static_cast<float>(c) + 0.5f);
}

TEST(Quantiser, RoundTripsWithinHalfAStepOverSeededRandomFaces) {
  const std::uint64_t seed = test::seed("Quantiser.RoundTrips");
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 2000; ++i) {
    FaceParams p;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const ChannelInfo& info = channel_table()[c];
      std::uniform_real_distribution<float> d(static_cast<float>(info.min_q) * info.step, static_cast<float>(info.max_q) * info.step);
      set_channel_value(p, c, d(rng));
    }
    const QuantisedParams q = quantise(p);
    const FaceParams back = dequantise(q);
    for (std::size_t c = 0; c < kChannelCount; ++c)
      ASSERT_LE(std::abs(channel_value(back, c) - channel_value(p, c)), channel_table()[c].step * 0.5001f)
          << channel_table()[c].name << " seed " << seed;
    ASSERT_EQ(quantise(back), q) << "dequantised values quantise to themselves";
  }
}

TEST(Quantiser, ClampsOutOfRangeAndTreatsNanAsRest) {
  FaceParams p;
  p.au[0] = 7.0f;
  p.head_yaw_rad = -10.0f;
  p.lid_left = std::numeric_limits<float>::quiet_NaN();
  p.pallor = std::numeric_limits<float>::infinity();
  const QuantisedParams q = quantise(p);
  EXPECT_EQ(q[0], 256);
  EXPECT_EQ(q[29], -1376);
  EXPECT_EQ(q[39], 0);
  EXPECT_EQ(q[46], 64);
}

TEST(Quantiser, RoundsToUnitsHalvesUpAlsoBelowZero) {
  EXPECT_EQ(round_to_units(5, 0), 5);
  EXPECT_EQ(round_to_units(5, 1), 3);
  EXPECT_EQ(round_to_units(-5, 1), -2);
  EXPECT_EQ(round_to_units(-6, 2), -1);
  EXPECT_EQ(round_to_units(-7, 2), -2);
  EXPECT_EQ(round_nearest(2.5), 3);
  EXPECT_EQ(round_nearest(-2.5), -3);
  EXPECT_EQ(clamp_coded(5000, 35), 2064);
}

}  // namespace
}  // namespace fw::codec
