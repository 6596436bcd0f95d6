#include "adaptive_bit.hpp"

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(AdaptiveBit, StartsEvenAndLearnsQuicklyThenSlowly) {
  AdaptiveBit b;
  EXPECT_EQ(b.p0, kProbabilityOne / 2);
  b.update(0);
  EXPECT_EQ(b.p0, kProbabilityOne / 2 + kProbabilityOne / 4) << "the first bit moves halfway";
  EXPECT_EQ(adaptation_shift(0), 1);
  EXPECT_EQ(adaptation_shift(2), 2);
  EXPECT_EQ(adaptation_shift(6), 3);
  EXPECT_EQ(adaptation_shift(kAdaptationSteps), 6);
  EXPECT_EQ(adaptation_shift(255), 6);
}

TEST(AdaptiveBit, StaysWithinItsBoundsWhateverItSees) {
  AdaptiveBit zeros, ones;
  for (int i = 0; i < 1000; ++i) {
    zeros.update(0);
    ones.update(1);
    ASSERT_GE(zeros.p0, kProbabilityMin);
    ASSERT_LE(zeros.p0, kProbabilityOne - kProbabilityMin);
    ASSERT_GE(ones.p0, kProbabilityMin);
  }
  // The slowest adaptation (shift 6) settles within 64 of certainty.
  EXPECT_GE(zeros.p0, kProbabilityOne - 64);
  EXPECT_LE(ones.p0, 64u);
  EXPECT_EQ(zeros.seen, kAdaptationSteps);
}

TEST(AdaptiveBit, TracksAChangeOfStatistics) {
  AdaptiveBit b;
  for (int i = 0; i < 200; ++i) b.update(0);
  for (int i = 0; i < 200; ++i) b.update(1);
  EXPECT_LT(b.p0, kProbabilityOne / 8) << "a forgetting window, not a lifetime count";
}

}  // namespace
}  // namespace fw::codec
