#include "fw/render/image_codec.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <webp/encode.h>

namespace fw::render {
namespace {

model::RgbaImage gradient(int w, int h) {
  model::RgbaImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = static_cast<std::uint8_t>(x * 8), p[1] = static_cast<std::uint8_t>(y * 8), p[2] = 90, p[3] = x < 4 ? 0 : 255;
    }
  return image;
}

std::vector<std::uint8_t> webp_lossless(const model::RgbaImage& image) {
  std::uint8_t* out = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(image.pixels.data(), image.width, image.height, image.width * 4, &out);
  std::vector<std::uint8_t> bytes(out, out + size);
  WebPFree(out);
  return bytes;
}

std::vector<std::uint8_t> png(const model::RgbaImage& image) {
  png_image p{};
  p.version = PNG_IMAGE_VERSION;
  p.width = static_cast<png_uint_32>(image.width);
  p.height = static_cast<png_uint_32>(image.height);
  p.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  png_image_write_to_memory(&p, nullptr, &size, 0, image.pixels.data(), 0, nullptr);
  std::vector<std::uint8_t> bytes(size);
  png_image_write_to_memory(&p, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr);
  return bytes;
}

TEST(ImageCodec, DecodesWebpAndPngExactly) {
  const model::RgbaImage original = gradient(24, 16);
  for (const auto& bytes : {webp_lossless(original), png(original)}) {
    model::RgbaImage decoded;
    std::string error;
    ASSERT_TRUE(decode_image(bytes, 64, decoded, error)) << error;
    EXPECT_EQ(decoded.width, 24);
    EXPECT_EQ(decoded.height, 16);
    // WebP keeps no colour under fully transparent pixels; everything seen is exact.
    for (std::size_t i = 0; i < original.pixels.size(); i += 4) {
      EXPECT_EQ(decoded.pixels[i + 3], original.pixels[i + 3]);
      if (original.pixels[i + 3] == 0) continue;
      for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(decoded.pixels[i + c], original.pixels[i + c]);
    }
  }
}

TEST(ImageCodec, RefusesImagesLargerThanAllowedBeforeDecoding) {
  model::RgbaImage decoded;
  std::string error;
  EXPECT_FALSE(decode_image(webp_lossless(gradient(24, 16)), 20, decoded, error));
  EXPECT_NE(error.find("24x16 pixels; at most 20"), std::string::npos) << error;
  EXPECT_FALSE(decode_image(png(gradient(24, 16)), 20, decoded, error));
}

TEST(ImageCodec, RefusesDamagedAndUnknownData) {
  model::RgbaImage decoded;
  std::string error;
  auto bytes = webp_lossless(gradient(24, 16));
  bytes.resize(bytes.size() / 2);
  EXPECT_FALSE(decode_image(bytes, 64, decoded, error));
  EXPECT_NE(error.find("damaged"), std::string::npos) << error;
  auto p = png(gradient(24, 16));
  p.resize(p.size() - 20);
  EXPECT_FALSE(decode_image(p, 64, decoded, error));
  EXPECT_FALSE(decode_image(std::vector<std::uint8_t>{1, 2, 3}, 64, decoded, error));
  EXPECT_NE(error.find("not a WebP or PNG"), std::string::npos);
}

}  // namespace
}  // namespace fw::render
