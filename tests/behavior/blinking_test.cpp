#include "fw/behavior/blinking.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

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

// Blinks are not all alike: their durations spread over the human range
// (100-400 ms, about 200 ms typical; blinking.hpp has the sources), and the
// lid is measured closed-to-open, as a viewer sees it at 30 Hz.
TEST(Blinking, DurationsVaryWithinTheHumanRange) {
  Blinking b(11);
  std::vector<double> durations;
  std::vector<double> seen;  // ticks with the lid moving, per blink, at 30 Hz
  int ticks_in_blink = 0;
  for (int i = 0; i < 30 * 900; ++i) {
    b.step(1.0 / 30, 0);
    if (b.started()) durations.push_back(b.duration_s());
    if (b.closure() > 0) {
      ++ticks_in_blink;
    } else if (ticks_in_blink > 0) {
      seen.push_back(ticks_in_blink / 30.0);
      ticks_in_blink = 0;
    }
  }
  ASSERT_GE(durations.size(), 100u);
  std::sort(durations.begin(), durations.end());
  const double median = durations[durations.size() / 2];
  const double p10 = durations[durations.size() / 10], p90 = durations[durations.size() * 9 / 10];
  std::printf("%zu blinks: 10th percentile %.0f ms, median %.0f ms, 90th %.0f ms\n", durations.size(), p10 * 1000,
              median * 1000, p90 * 1000);
  EXPECT_GE(durations.front(), 0.1);
  EXPECT_LE(durations.back(), 0.4);
  EXPECT_NEAR(median, 0.2, 0.03);
  EXPECT_GT(p90 - p10, 0.08) << "durations hardly vary";
  // What a viewer sees lasts as long as the blink, to a tick.
  std::sort(seen.begin(), seen.end());
  EXPECT_NEAR(seen[seen.size() / 2], median, 1.5 / 30);
}

TEST(Blinking, LidsFollowTheEyesDown) {
  EXPECT_EQ(lid_follows_pitch(0.2f), 0.0f);
  EXPECT_GT(lid_follows_pitch(-0.3f), 0.2f);
  EXPECT_LE(lid_follows_pitch(-2.0f), 0.45f);
}

}  // namespace
}  // namespace fw::behavior
