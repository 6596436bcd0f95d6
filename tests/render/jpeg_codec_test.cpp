#include "fw/render/jpeg_codec.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

namespace fw::render {
namespace {

// A smooth colour ramp: what JPEG codes well, so the round trip stays close.
model::RgbaImage ramp(int width, int height) {
  model::RgbaImage image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = static_cast<std::uint8_t>(255 * x / (width - 1));
      p[1] = static_cast<std::uint8_t>(255 * y / (height - 1));
      p[2] = 128;
      p[3] = 255;
    }
  return image;
}

TEST(JpegCodec, RoundTripKeepsSizeAndColoursClose) {
  const model::RgbaImage original = ramp(64, 48);
  std::vector<std::uint8_t> bytes;
  std::string error;
  ASSERT_TRUE(encode_jpeg(original, 90, bytes, error)) << error;
  EXPECT_TRUE(is_jpeg(bytes));
  model::RgbaImage decoded;
  ASSERT_TRUE(decode_jpeg(bytes, 4096, decoded, error)) << error;
  ASSERT_EQ(decoded.width, 64);
  ASSERT_EQ(decoded.height, 48);
  int worst = 0;
  for (std::size_t i = 0; i < original.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(original.pixels[i]) - int(decoded.pixels[i])));
  EXPECT_LE(worst, 12);
  EXPECT_EQ(decoded.at(10, 10)[3], 255);
}

TEST(JpegCodec, LowerQualityMakesSmallerFiles) {
  const model::RgbaImage original = ramp(200, 200);
  std::vector<std::uint8_t> high, low;
  std::string error;
  ASSERT_TRUE(encode_jpeg(original, 95, high, error)) << error;
  ASSERT_TRUE(encode_jpeg(original, 20, low, error)) << error;
  EXPECT_LT(low.size(), high.size());
}

TEST(JpegCodec, RefusesAnImageLargerThanTheLimitBeforeDecodingIt) {
  std::vector<std::uint8_t> bytes;
  std::string error;
  ASSERT_TRUE(encode_jpeg(ramp(300, 20), 80, bytes, error)) << error;
  model::RgbaImage decoded;
  EXPECT_FALSE(decode_jpeg(bytes, 256, decoded, error));
  EXPECT_NE(error.find("300x20"), std::string::npos) << error;
}

TEST(JpegCodec, DamagedFilesFailWithAMessage) {
  std::vector<std::uint8_t> bytes;
  std::string error;
  ASSERT_TRUE(encode_jpeg(ramp(32, 32), 80, bytes, error)) << error;
  model::RgbaImage decoded;
  const std::vector<std::uint8_t> header_only(bytes.begin(), bytes.begin() + 20);
  EXPECT_FALSE(decode_jpeg(header_only, 4096, decoded, error));
  EXPECT_NE(error.find("JPEG"), std::string::npos);
  const std::vector<std::uint8_t> png_like = {0x89, 'P', 'N', 'G'};
  EXPECT_FALSE(decode_jpeg(png_like, 4096, decoded, error));
  EXPECT_EQ(error, "not a JPEG image");
  EXPECT_FALSE(encode_jpeg(model::RgbaImage{}, 80, bytes, error));
}

}  // namespace
}  // namespace fw::render
