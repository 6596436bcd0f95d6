#include "rate_controller.hpp"

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(RateController, StartsAtTheVisibleLevelWithinItsRange) {
  EXPECT_EQ(RateController(500, 30, 0, 7).level(), 3);
  EXPECT_EQ(RateController(500, 30, 5, 7).level(), 5);
  EXPECT_EQ(RateController(500, 30, 0, 1).level(), 1);
  const RateController r(600, 30, 0, 7);
  EXPECT_DOUBLE_EQ(r.bits_per_tick(), 20.0);
  EXPECT_DOUBLE_EQ(r.capacity_bits(), 1800.0);
}

TEST(RateController, TheBucketRefusesFramesThatWouldOverflowIt) {
  RateController r(300, 30, 0, 7);  // 10 bits per tick, 900 in the bucket
  EXPECT_TRUE(r.allows(5000)) << "an empty bucket takes any one frame";
  r.on_frame_sent(850, false);
  EXPECT_FALSE(r.allows(100));
  EXPECT_TRUE(r.allows(100, true)) << "urgent frames use the reserve";
  for (int i = 0; i < 10; ++i) r.on_tick();
  EXPECT_TRUE(r.allows(100));
}

TEST(RateController, GoesCoarserWhenSpendingTooMuchAndFinerWhenNot) {
  RateController r(300, 30, 0, 7);
  const int start = r.level();
  for (int t = 0; t < 300; ++t) {
    r.on_tick();
    r.on_frame_sent(30, false);  // three times the budget
  }
  EXPECT_EQ(r.level(), 7);
  EXPECT_GT(r.level(), start);
  for (int t = 0; t < 3000; ++t) r.on_tick();  // silence
  EXPECT_EQ(r.level(), 0);
}

TEST(RateController, OptionalBitsFillTheBucketButNeverCoarsenTheLevel) {
  // The corrective weights go on spare budget: their bits count against the
  // bucket (the budget holds) but not in the spending that sets the level.
  RateController r(300, 30, 0, 7);  // 10 bits per tick
  const int start = r.level();
  for (int t = 0; t < 300; ++t) {
    r.on_tick();
    r.on_frame_sent(9, false, 6);  // 3 bits of the face's own, 6 of correctives: 90 % of the budget
  }
  EXPECT_LE(r.level(), start) << "the face alone spends under a third of its budget";
  EXPECT_LT(r.pressure(), 0.75);
  r.on_frame_sent(800, false, 800);
  EXPECT_FALSE(r.allows(200)) << "but optional bits fill the bucket like any";
}

TEST(RateController, ABudgetChangeTakesEffect) {
  RateController r(3000, 30, 0, 7);
  for (int t = 0; t < 600; ++t) {
    r.on_tick();
    r.on_frame_sent(40, false);  // 1200 bit/s: comfortably under 3000
  }
  const int relaxed = r.level();
  r.set_target_bps(300);
  for (int t = 0; t < 600; ++t) {
    r.on_tick();
    if (r.allows(40)) r.on_frame_sent(40, false);
  }
  EXPECT_GT(r.level(), relaxed);
  EXPECT_DOUBLE_EQ(r.capacity_bits(), 900.0);
}

TEST(RateController, KeyFramesTakeAnEighthOfTheBudgetWithinLimits) {
  RateController r(600, 30, 0, 7);  // 20 bits per tick
  EXPECT_EQ(r.key_interval_ticks(300), 100) << "8 * 250 default bits / 20";
  r.on_frame_sent(400, true);
  EXPECT_EQ(r.key_interval_ticks(300), 160);
  EXPECT_EQ(r.key_interval_ticks(90), 90) << "never longer than asked";
  RateController rich(100000, 30, 0, 7);
  rich.on_frame_sent(400, true);
  EXPECT_EQ(rich.key_interval_ticks(300), 60) << "never more often than every 2 s";
}

}  // namespace
}  // namespace fw::codec
