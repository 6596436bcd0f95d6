#include "fw/behavior/gradient_noise.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(GradientNoise, ZeroAtLatticePoints) {
  for (int i = -5; i <= 5; ++i) EXPECT_FLOAT_EQ(gradient_noise(static_cast<float>(i), 7u), 0.0f);
}

TEST(GradientNoise, BoundedSmoothAndVaried) {
  float low = 1, high = -1, largest_step = 0;
  float previous = gradient_noise(0.0f, 3u);
  for (int i = 1; i < 20000; ++i) {
    const float v = gradient_noise(static_cast<float>(i) * 0.001f, 3u);
    low = std::min(low, v);
    high = std::max(high, v);
    largest_step = std::max(largest_step, std::abs(v - previous));
    previous = v;
  }
  EXPECT_GE(low, -0.5f);
  EXPECT_LE(high, 0.5f);
  EXPECT_GT(high - low, 0.3f) << "it actually moves";
  EXPECT_LT(largest_step, 0.005f) << "no jumps between samples 1 ms apart";
}

TEST(GradientNoise, SeedsGiveIndependentReproducibleSequences) {
  EXPECT_FLOAT_EQ(gradient_noise(2.37f, 11u), gradient_noise(2.37f, 11u));
  int differing = 0;
  for (int i = 0; i < 50; ++i) {
    const float t = 0.5f + static_cast<float>(i) * 0.73f;
    differing += std::abs(gradient_noise(t, 1u) - gradient_noise(t, 2u)) > 1e-3f;
  }
  EXPECT_GT(differing, 40);
}

}  // namespace
}  // namespace fw::behavior
