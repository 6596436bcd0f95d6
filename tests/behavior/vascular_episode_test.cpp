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

// Peak cheek blush over 30 s of a face attended by `n` of `others` faces,
// embarrassed at the start when `embarrassed`.
float peak_blush(int n, int others, bool embarrassed) {
  VascularState v;
  if (embarrassed) v.embarrass();
  float peak = 0;
  for (int i = 0; i < 30 * 30; ++i) {
    v.step(1.0 / 30, n, others, 0, 0);
    codec::FaceParams p;
    v.write(p);
    peak = std::max(peak, p.blush[kCheek]);
  }
  return peak;
}

// Being looked at is what conversation is: one face looking, or a few of a
// crowd, starts no blush however long it lasts.
TEST(VascularState, BeingLookedAtIsNoCause) {
  EXPECT_EQ(peak_blush(0, 3, false), 0);
  EXPECT_EQ(peak_blush(1, 1, false), 0);
  EXPECT_EQ(peak_blush(1, 4, false), 0);
  EXPECT_EQ(peak_blush(2, 7, false), 0);
}

// The centre of everyone's attention for a while blushes (Leary et al. 1992).
TEST(VascularState, TheCentreOfAttentionForAWhileBlushes) {
  VascularState v;
  std::optional<std::string> started;
  int ticks = 0;
  while (!started && ticks < 30 * 20) {
    started = v.step(1.0 / 30, 2, 2, 0, 0);
    ++ticks;
  }
  ASSERT_TRUE(started) << "never blushed";
  EXPECT_NEAR(ticks / 30.0, VascularState::kSpotlightS, 0.1);
  EXPECT_NE(started->find("centre of attention"), std::string::npos) << *started;
}

// Embarrassment blushes at once, the more the larger the audience (Shearn
// et al., cited in section 6).
TEST(VascularState, EmbarrassmentBlushesMoreBeforeALargerAudience) {
  const float none = peak_blush(0, 4, true), one = peak_blush(1, 4, true), two = peak_blush(2, 4, true),
              four = peak_blush(4, 4, true);
  EXPECT_GT(none, 0.1f);
  EXPECT_LT(none, one);
  EXPECT_LT(one, two);
  EXPECT_LT(two, four);
  EXPECT_LT(VascularState::blush_span_s(1), VascularState::blush_span_s(4));
}

TEST(VascularState, NoNewBlushWithinTheRefractoryTime) {
  VascularState v;
  v.embarrass();
  ASSERT_TRUE(v.step(1.0 / 30, 0, 2, 0, 0));
  for (int i = 0; i < 30 * 20; ++i) v.step(1.0 / 30, 0, 2, 0, 0);
  v.embarrass();
  EXPECT_FALSE(v.step(1.0 / 30, 0, 2, 0, 0)) << "20 s after the first";
}

TEST(VascularState, ColourOutlastsTheMuscularExpression) {
  // A blush lasts longer than any expression command's few seconds.
  EXPECT_GT(VascularState::blush_span_s(1), 10);
}

TEST(VascularState, FearPales) {
  VascularState v;
  const auto started = v.step(1.0 / 30, 0, 1, 0.9f, 0);
  ASSERT_TRUE(started);
  EXPECT_EQ(*started, "pallor start");
  for (int i = 0; i < 30; ++i) v.step(1.0 / 30, 0, 1, 0, 0);
  codec::FaceParams p;
  v.write(p);
  EXPECT_GT(p.pallor, 0.3f);
}

}  // namespace
}  // namespace fw::behavior
