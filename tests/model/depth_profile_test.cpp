#include "fw/model/depth_profile.hpp"

#include <gtest/gtest.h>

#include "fw/model/landmark_template.hpp"

namespace fw::model {
namespace {

float depth_at(int landmark) { return face_depth(landmark_template()[static_cast<std::size_t>(landmark)]); }

TEST(DepthProfile, NoseTipIsTheMostForwardLandmark) {
  for (int i = 0; i < kLandmarkCount; ++i)
    if (i != landmarks::kNoseTip) {
      EXPECT_LT(depth_at(i), depth_at(landmarks::kNoseTip)) << "landmark " << i;
    }
}

TEST(DepthProfile, EyesSitDeeperThanBrowsAndCheeks) {
  EXPECT_LT(depth_at(37), depth_at(19)) << "upper lid under the brow ridge";
  EXPECT_LT(face_depth({0.5f, 0.0f}), face_depth({0.0f, -0.2f})) << "eye behind the nose bridge";
}

TEST(DepthProfile, SidesCurveBackLikeAHead) {
  EXPECT_LT(depth_at(0), depth_at(36) - 0.25f) << "jaw angle well behind the eye corner";
  EXPECT_LT(face_depth({1.35f, 0.0f}), depth_at(0)) << "ears behind the jaw line";
  EXPECT_LT(face_depth({0.0f, 1.5f}), face_depth({0.0f, 0.6f})) << "forehead slopes back";
}

TEST(DepthProfile, IsSymmetricAndSmooth) {
  for (float y = -2.0f; y <= 1.6f; y += 0.1f)
    for (float x = 0.0f; x <= 1.4f; x += 0.1f) {
      EXPECT_FLOAT_EQ(face_depth({x, y}), face_depth({-x, y}));
      // No cliffs: a step of 0.01 units never changes depth by more than 0.05.
      EXPECT_LT(std::abs(face_depth({x + 0.01f, y}) - face_depth({x, y})), 0.05f) << x << "," << y;
      EXPECT_LT(std::abs(face_depth({x, y + 0.01f}) - face_depth({x, y})), 0.05f) << x << "," << y;
    }
}

}  // namespace
}  // namespace fw::model
