#include "fw/behavior/vascular_episode.hpp"

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

constexpr std::size_t kCheek = static_cast<std::size_t>(codec::ColourRegion::cheek_left);

TEST(VascularEpisode, BlushingHasThePapersFourStages) {
  const script::VascularEmotion& blush = builtin_vascular_emotion("blushing");
  ASSERT_EQ(blush.stages.size(), 4u);
  EXPECT_EQ(blush.stages[0].duration_percent, 10);
  EXPECT_EQ(blush.stages[1].duration_percent, 10);
  EXPECT_EQ(blush.stages[2].duration_percent, 60);
  EXPECT_EQ(blush.stages[3].duration_percent, 20);
  // Colour rises in the first 20%, holds through the sustain, releases to nothing.
  const double span = 20;
  EXPECT_EQ(episode_colour(blush, 0, span, 1)[kCheek], 0);
  EXPECT_NEAR(episode_colour(blush, 0.2 * span, span, 1)[kCheek], 0.8 * 0.8, 1e-6);
  EXPECT_NEAR(episode_colour(blush, 0.8 * span, span, 1)[kCheek], 0.6 * 0.7, 1e-6);
  EXPECT_NEAR(episode_colour(blush, 0.999 * span, span, 1)[kCheek], 0, 0.01);
  EXPECT_EQ(episode_colour(blush, span + 1, span, 1)[kCheek], 0);
}

TEST(VascularEpisode, PallorPalesTheWholeFace) {
  const script::VascularEmotion& pallor = builtin_vascular_emotion("pallor");
  EXPECT_GT(episode_colour(pallor, 2, 8, 1)[script::kPallorChannel], 0.5);
  EXPECT_EQ(episode_colour(pallor, 2, 8, 1)[kCheek], 0);
}

// Peak cheek blush of a face stared at by `n` faces for 30 s.
float peak_blush(int n) {
  VascularState v;
  float peak = 0;
  for (int i = 0; i < 30 * 30; ++i) {
    v.step(1.0 / 30, n, 0, 0);
    codec::FaceParams p;
    v.write(p);
    peak = std::max(peak, p.blush[kCheek]);
  }
  return peak;
}

TEST(VascularState, BlushingGrowsWithTheNumberOfAttendingFaces) {
  EXPECT_EQ(peak_blush(0), 0);
  const float one = peak_blush(1), two = peak_blush(2), four = peak_blush(4);
  EXPECT_GT(one, 0.1f);
  EXPECT_LT(one, two);
  EXPECT_LT(two, four);
  EXPECT_LT(VascularState::blush_span_s(1), VascularState::blush_span_s(4));
}

TEST(VascularState, ColourOutlastsTheMuscularExpression) {
  // A blush lasts longer than any expression command's few seconds.
  EXPECT_GT(VascularState::blush_span_s(1), 10);
}

TEST(VascularState, FearPales) {
  VascularState v;
  const auto started = v.step(1.0 / 30, 0, 0.9f, 0);
  ASSERT_TRUE(started);
  EXPECT_EQ(*started, "pallor start");
  for (int i = 0; i < 30; ++i) v.step(1.0 / 30, 0, 0, 0);
  codec::FaceParams p;
  v.write(p);
  EXPECT_GT(p.pallor, 0.3f);
}

}  // namespace
}  // namespace fw::behavior
