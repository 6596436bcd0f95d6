#include "fw/behavior/blinking.hpp"

#include <cstdio>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

class BlinkRate : public ::testing::TestWithParam<std::uint64_t> {};

// Ten minutes with a gaze shift of 10-60 degrees every ~2 s.
TEST_P(BlinkRate, TenToThirtyAMinute) {
  const std::uint64_t seed = GetParam();
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  Blinking b(seed);
  const double dt = 1.0 / 30;
  const int ticks = 30 * 600;
  for (int i = 0; i < ticks; ++i) {
    const float saccade = (i % 61 == 0) ? 0.17f + 0.87f * static_cast<float>((i / 61) % 5) / 4.0f : 0.0f;
    b.step(dt, saccade);
  }
  const double per_minute = b.count() / 10.0;
  EXPECT_GE(per_minute, 10);
  EXPECT_LE(per_minute, 30);
}

INSTANTIATE_TEST_SUITE_P(Seeds, BlinkRate, ::testing::Values(1u, 7u, 42u));

TEST(Blinking, LargeSaccadesBlinkMoreOften) {
  Blinking calm(5), shifting(5);
  for (int i = 0; i < 30 * 300; ++i) {
    calm.step(1.0 / 30, 0);
    shifting.step(1.0 / 30, i % 60 == 0 ? 1.0f : 0.0f);
  }
  EXPECT_GT(shifting.count(), calm.count());
}

TEST(Blinking, ABlinkClosesTheLidFullyAndReopens) {
  Blinking b(1);
  float most = 0;
  bool reopened = false;
  for (int i = 0; i < 30 * 20; ++i) {
    b.step(1.0 / 30, 0);
    most = std::max(most, b.closure());
    if (most == 1 && b.closure() == 0) reopened = true;
  }
  EXPECT_EQ(most, 1.0f);
  EXPECT_TRUE(reopened);
}

TEST(Blinking, LidsFollowTheEyesDown) {
  EXPECT_EQ(lid_follows_pitch(0.2f), 0.0f);
  EXPECT_GT(lid_follows_pitch(-0.3f), 0.2f);
  EXPECT_LE(lid_follows_pitch(-2.0f), 0.45f);
}

}  // namespace
}  // namespace fw::behavior
