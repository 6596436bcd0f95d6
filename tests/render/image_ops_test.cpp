#include "fw/render/image_ops.hpp"

#include <gtest/gtest.h>

namespace fw::render {
namespace {

TEST(ImageOps, DotIsRoundAndClipped) {
  model::RgbaImage image(20, 20);
  draw_dot(image, {10, 10}, 3.0f, {255, 0, 0});
  EXPECT_EQ(image.at(10, 10)[0], 255);
  EXPECT_EQ(image.at(12, 10)[0], 255);
  EXPECT_EQ(image.at(13, 13)[0], 0) << "corner of the box is outside the disc";
  draw_dot(image, {-5, -5}, 100.0f, {0, 255, 0});  // covers everything, clipped to the image
  EXPECT_EQ(image.at(19, 19)[1], 255);
}

TEST(ImageOps, PasteCompositesByAlphaAndClips) {
  model::RgbaImage target(4, 4), source(3, 3);
  for (auto& v : target.pixels) v = 100;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      std::uint8_t* p = source.at(x, y);
      p[0] = p[1] = p[2] = 200;
      p[3] = x == 0 ? 0 : 255;
    }
  paste(target, source, 2, 2);
  EXPECT_EQ(target.at(2, 2)[0], 100) << "transparent source keeps the target";
  EXPECT_EQ(target.at(3, 3)[0], 200);
  EXPECT_EQ(target.at(1, 1)[0], 100);
}

TEST(ImageOps, ResizeKeepsAFlatColourAndTheSize) {
  model::RgbaImage flat(7, 5);
  for (auto& v : flat.pixels) v = 77;
  const model::RgbaImage big = resized(flat, 30, 11);
  EXPECT_EQ(big.width, 30);
  EXPECT_EQ(big.height, 11);
  for (auto v : big.pixels) EXPECT_EQ(v, 77);
}

}  // namespace
}  // namespace fw::render
