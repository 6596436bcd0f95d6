#include "fw/model/landmark_template.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace fw::model {
namespace {

namespace lm = landmarks;

glm::vec2 centre_of(int begin, int end) {
  glm::vec2 sum(0.0f);
  for (int i = begin; i < end; ++i) sum += landmark_template()[static_cast<std::size_t>(i)];
  return sum / static_cast<float>(end - begin);
}

TEST(LandmarkTemplate, EyeCentresDefineTheFrame) {
  const glm::vec2 right = centre_of(lm::kEyeRightBegin, lm::kEyeRightEnd);
  const glm::vec2 left = centre_of(lm::kEyeLeftBegin, lm::kEyeLeftEnd);
  EXPECT_NEAR(glm::length(left - right), 1.0f, 1e-3f) << "one unit is the inter-ocular distance";
  EXPECT_NEAR((left + right).x, 0.0f, 1e-3f);
  EXPECT_NEAR((left + right).y, 0.0f, 1e-3f);
  EXPECT_LT(right.x, left.x) << "the person's right eye is on the viewer's left";
}

TEST(LandmarkTemplate, IsMirrorSymmetric) {
  const auto t = landmark_template();
  for (int i = 0; i < kLandmarkCount; ++i) {
    const int m = mirrored_landmark(i);
    EXPECT_EQ(mirrored_landmark(m), i);
    EXPECT_FLOAT_EQ(t[static_cast<std::size_t>(i)].x, -t[static_cast<std::size_t>(m)].x) << "landmark " << i;
    EXPECT_FLOAT_EQ(t[static_cast<std::size_t>(i)].y, t[static_cast<std::size_t>(m)].y) << "landmark " << i;
  }
}

TEST(LandmarkTemplate, FeaturesAreWhereAFaceHasThem) {
  const auto t = landmark_template();
  const float brows = centre_of(lm::kBrowRightBegin, lm::kBrowLeftEnd).y;
  const float nose_tip = t[lm::kNoseTip].y;
  const float mouth = centre_of(lm::kOuterLipBegin, lm::kOuterLipEnd).y;
  const float chin = t[lm::kChin].y;
  EXPECT_GT(brows, 0.0f);
  EXPECT_LT(nose_tip, 0.0f);
  EXPECT_LT(mouth, nose_tip);
  EXPECT_LT(chin, mouth);
  // Closed lips at rest: upper and lower inner lip a hair apart, never crossed.
  for (int upper : {61, 62, 63}) {
    const int lower = 128 - upper;  // 61<->67, 62<->66, 63<->65
    const float gap = t[static_cast<std::size_t>(upper)].y - t[static_cast<std::size_t>(lower)].y;
    EXPECT_GT(gap, 0.0f);
    EXPECT_LT(gap, 0.03f);
  }
}

}  // namespace
}  // namespace fw::model
