#include "opaque_texels.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "colour_mipmaps.hpp"

namespace fw::render {
namespace {

constexpr int kSize = 64;

// An opaque grey image with a translucent 4x4 block at its top right corner
// (image rows run top down: the block is at high u and high v).
model::RgbaImage with_translucent_corner(bool translucent = true) {
  model::RgbaImage image(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = p[1] = p[2] = 128;
      p[3] = translucent && x >= kSize - 4 && y < 4 ? 0 : 255;
    }
  return image;
}

TEST(OpaqueTexels, AnOpaqueTextureIsOpaqueAtEveryLevel) {
  const OpaqueTexels texels(square_root_light_mipmaps(with_translucent_corner(false)));
  EXPECT_EQ(texels.level_count(), 7);  // 64 .. 1
  EXPECT_EQ(texels.opaque_levels({0.0f, 0.0f}, {1.0f, 1.0f}), 7);
  EXPECT_EQ(texels.size(), glm::vec2(kSize, kSize));
}

TEST(OpaqueTexels, AFootprintOverTheTranslucentTexelsIsNotOpaque) {
  const OpaqueTexels texels(square_root_light_mipmaps(with_translucent_corner()));
  EXPECT_EQ(texels.opaque_levels({0.9f, 0.9f}, {1.0f, 1.0f}), 0);
}

TEST(OpaqueTexels, FarFromTheTranslucentTexelsOnlyTheSmallLevelsReachThem) {
  const OpaqueTexels texels(square_root_light_mipmaps(with_translucent_corner()));
  const int levels = texels.opaque_levels({0.05f, 0.05f}, {0.3f, 0.3f});
  // The large levels keep the corner apart; the small ones average it into
  // texels this footprint reads (the 1x1 level into its only texel).
  EXPECT_GE(levels, 3);
  EXPECT_LT(levels, texels.level_count());
}

TEST(OpaqueTexels, TheMarginReachesTexelsJustBeyondTheFootprint) {
  const OpaqueTexels texels(square_root_light_mipmaps(with_translucent_corner()));
  // The block starts at u = 60/64; a footprint ending two texels short of
  // it still reads it (a pixel centre outside its triangle reads beyond).
  EXPECT_EQ(texels.opaque_levels({0.5f, 0.5f}, {58.0f / kSize, 1.0f}), 0);
  EXPECT_GT(texels.opaque_levels({0.5f, 0.5f}, {50.0f / kSize, 1.0f}), 0);
}

// Orthographic: model x and y in [-1, 1] fill a 100x100 viewport.
const glm::mat4 kFill = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -10.0f, 10.0f);
const std::array<glm::vec3, 3> kCorners{glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(-1, 1, 0)};
const std::array<glm::vec2, 3> kUvs{glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1)};

TEST(HighestLevelRead, FollowsTexelsPerPixelPlusTwo) {
  // 400 texels over 100 pixels: level 2, so levels up to 4 may be read.
  EXPECT_EQ(highest_level_read(kCorners, kUvs, {400.0f, 400.0f}, 9, kFill, {100.0f, 100.0f}), 4);
  // Magnified (half a texel a pixel): level 0 and the next two at most.
  EXPECT_EQ(highest_level_read(kCorners, kUvs, {50.0f, 50.0f}, 7, kFill, {100.0f, 100.0f}), 1);
  // Never beyond the last level.
  EXPECT_EQ(highest_level_read(kCorners, kUvs, {4096.0f, 4096.0f}, 3, kFill, {100.0f, 100.0f}), 2);
}

TEST(HighestLevelRead, IsTheLastLevelWhenItCannotBeTold) {
  const glm::mat4 perspective = glm::perspective(1.0f, 1.0f, 0.1f, 100.0f);
  // A corner behind the camera.
  EXPECT_EQ(highest_level_read({glm::vec3(-1, -1, -5), glm::vec3(1, -1, 5), glm::vec3(-1, 1, -5)}, kUvs,
                               {64.0f, 64.0f}, 7, perspective, {100.0f, 100.0f}),
            6);
  // Seen edge on.
  EXPECT_EQ(highest_level_read({glm::vec3(-1, 0, -1), glm::vec3(1, 0, -1), glm::vec3(0, 0, 1)}, kUvs,
                               {64.0f, 64.0f}, 7, kFill, {100.0f, 100.0f}),
            6);
}

TEST(SortOpaqueFirst, PutsTheTrianglesThatReadOnlyOpaqueTexelsFirst) {
  const OpaqueTexels texels(square_root_light_mipmaps(with_translucent_corner()));
  // Two triangles filling the viewport: the second's uvs cover the corner.
  const std::vector<glm::vec3> positions{{-1, -1, 0}, {0, -1, 0}, {-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<glm::vec2> uvs{{0.0f, 0.0f}, {0.3f, 0.0f}, {0.0f, 0.3f}, {0.7f, 0.7f}, {1.0f, 0.7f}, {0.7f, 1.0f}};
  const std::vector<glm::uvec3> triangles{{3, 4, 5}, {0, 1, 2}};
  const TexelOpacity opacity = texel_opacity(triangles, uvs, texels);
  EXPECT_FALSE(opacity.all_opaque());
  std::vector<glm::uvec3> sorted;
  // About a texel a pixel: the far triangle reads only the large levels.
  EXPECT_EQ(sort_opaque_first(opacity, positions, uvs, kFill, {40.0f, 40.0f}, sorted), 1u);
  ASSERT_EQ(sorted.size(), 2u);
  EXPECT_EQ(sorted[0], triangles[1]);
  EXPECT_EQ(sorted[1], triangles[0]);
  // Seen so small that it reads the levels which hold the corner: none.
  EXPECT_EQ(sort_opaque_first(opacity, positions, uvs, kFill, {1.0f, 1.0f}, sorted), 0u);
}

}  // namespace
}  // namespace fw::render
