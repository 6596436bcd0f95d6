#include "fw/behavior/emotion_space.hpp"

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(EmotionSpace, TemplatesPartitionTheCube) {
  EXPECT_EQ(label(classify({})), "neutral");
  EXPECT_EQ(label(classify({0.1f, 0.1f, 0, 0, 0, 0})), "neutral");
  EXPECT_EQ(label(classify({0.8f, 0, 0, 0, 0.2f, 0})), "joy");
  EXPECT_EQ(label(classify({0, 0, 0, 0.7f, 0.6f, 0})), "fear+surprise");
  EXPECT_EQ(label(classify({0, 0, 0.5f, 0, 0, 0.9f})), "disgust");
  EXPECT_EQ(*classify({0, 0, 0.5f, 0, 0, 0.9f}).first, Primary::disgust);
}

TEST(EmotionSpace, DecaysTowardNeutralByHalfLives) {
  const EmotionPoint p = decay_toward_neutral({1, 0.5f, 0, 0, 0, 0}, 4.0, 2.0);
  EXPECT_NEAR(p[0], 0.25f, 1e-5);
  EXPECT_NEAR(p[1], 0.125f, 1e-5);
}

TEST(EmotionSpace, PrimariesMapThroughTheModelsExpressionTable) {
  const auto joy = emotion_action_units({1, 0, 0, 0, 0, 0});
  codec::FaceParams p;
  p.au = joy;
  EXPECT_GT(p.au_intensity(12), 0.5f);  // lip corner puller
  EXPECT_EQ(p.au_intensity(4), 0);
  const auto none = emotion_action_units({});
  for (float v : none) EXPECT_EQ(v, 0);
  EXPECT_EQ(primary_from_name("fear"), Primary::fear);
  EXPECT_FALSE(primary_from_name("neutral"));
}

TEST(EmotionSpace, ClampKeepsPointsInTheCube) {
  const EmotionPoint p = clamp_to_cube({-1, 2, 0.5f, 0, 0, 0});
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 1);
  EXPECT_EQ(p[2], 0.5f);
}

}  // namespace
}  // namespace fw::behavior
