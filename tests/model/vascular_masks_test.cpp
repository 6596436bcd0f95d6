#include "fw/model/vascular_masks.hpp"

#include <gtest/gtest.h>

namespace fw::model {
namespace {

constexpr int kSize = 64;

std::uint8_t at(const Mask& mask, const TextureFrame& frame, glm::vec2 p) {
  const glm::vec2 uv = frame.to_uv(p);
  return mask[static_cast<std::size_t>(static_cast<int>((1 - uv.y) * kSize) * kSize + static_cast<int>(uv.x * kSize))];
}

TEST(VascularMasks, ShadeIsOneAtTheHeartAndZeroAtTheBorder) {
  EXPECT_NEAR(evaluate_shade(0.5f, 0.5f), 1.0f, 1e-6f);
  for (float t : {0.0f, 0.3f, 1.0f}) {
    EXPECT_NEAR(evaluate_shade(0.0f, t), 0.0f, 1e-6f);
    EXPECT_NEAR(evaluate_shade(t, 1.0f), 0.0f, 1e-6f);
  }
}

TEST(VascularMasks, PatchCornersAreTheControlCorners) {
  const BezierPatch patch = region_patches(MaskRegion::forehead)[0];
  EXPECT_EQ(evaluate_patch(patch, 0, 0), patch[0][0]);
  EXPECT_EQ(evaluate_patch(patch, 1, 1), patch[3][3]);
}

TEST(VascularMasks, RegionsCoverTheirPartOfTheFace) {
  const TextureFrame& frame = generic_face().texture_frame;
  const auto masks = render_region_masks([](glm::vec2 p) { return p; }, frame, kSize);
  const auto mask = [&](MaskRegion r) { return masks[static_cast<std::size_t>(r)]; };
  EXPECT_GT(at(mask(MaskRegion::cheek_left), frame, {0.65f, -0.55f}), 200);
  EXPECT_EQ(at(mask(MaskRegion::cheek_left), frame, {-0.65f, -0.55f}), 0) << "the other cheek";
  EXPECT_EQ(at(mask(MaskRegion::cheek_left), frame, {0.0f, -0.2f}), 0) << "the nose bridge";
  EXPECT_GT(at(mask(MaskRegion::forehead), frame, {0.0f, 0.85f}), 200);
  EXPECT_GT(at(mask(MaskRegion::nose), frame, {0.0f, -0.4f}), 150);
  EXPECT_GT(at(mask(MaskRegion::sides), frame, {1.2f, -0.3f}), 150);
  EXPECT_GT(at(mask(MaskRegion::face), frame, {0.0f, -0.3f}), 200);
  EXPECT_EQ(at(mask(MaskRegion::face), frame, {1.9f, 1.6f}), 0) << "outside the head";
}

TEST(VascularMasks, FollowTheWarp) {
  const TextureFrame& frame = generic_face().texture_frame;
  const auto shifted = render_region_masks([](glm::vec2 p) { return p + glm::vec2(0.3f, 0.0f); }, frame, kSize);
  EXPECT_GT(at(shifted[static_cast<std::size_t>(MaskRegion::cheek_left)], frame, {0.95f, -0.55f}), 200);
}

TEST(VascularMasks, PackThreeRegionsPerImage) {
  const TextureFrame& frame = generic_face().texture_frame;
  const auto masks = render_region_masks([](glm::vec2 p) { return p; }, frame, kSize);
  const auto packed = pack_region_masks(masks, kSize);
  for (std::size_t i = 0; i < masks[0].size(); i += 97) {
    EXPECT_EQ(packed[0].pixels[i * 4 + 1], masks[1][i]) << "green = left cheek";
    EXPECT_EQ(packed[1].pixels[i * 4 + 2], masks[5][i]) << "blue = whole face";
  }
}

}  // namespace
}  // namespace fw::model
