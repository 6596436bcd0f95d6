#include "photo_downsizer.hpp"

#include <random>

#include <gtest/gtest.h>

#include "fw/model/file_io.hpp"
#include "fw/render/jpeg_codec.hpp"
#include "test_paths.hpp"

namespace fw::client {
namespace {

// A large photo-like image: smooth gradients with seeded noise, which JPEG
// cannot compress to nothing.
model::RgbaImage noisy_photo(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> noise(-20, 20);
  model::RgbaImage image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = static_cast<std::uint8_t>(std::clamp(100 + 100 * x / width + noise(random), 0, 255));
      p[1] = static_cast<std::uint8_t>(std::clamp(80 + 120 * y / height + noise(random), 0, 255));
      p[2] = static_cast<std::uint8_t>(std::clamp(120 + noise(random), 0, 255));
      p[3] = 255;
    }
  return image;
}

TEST(PhotoDownsizer, ALargePhotoBecomesASmallJpegOfAtMost640Pixels) {
  const unsigned seed = 7;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::vector<std::uint8_t> original;
  std::string error;
  ASSERT_TRUE(render::encode_jpeg(noisy_photo(2000, 1500, seed), 95, original, error)) << error;
  ASSERT_GT(original.size(), 300u * 1024);
  DownsizedPhoto photo;
  ASSERT_TRUE(downsize_photo(original, photo, error)) << error;
  EXPECT_LE(photo.jpeg.size(), kTargetUploadBytes + kTargetUploadBytes / 10);
  EXPECT_LE(std::max(photo.width, photo.height), kMaxUploadSide);
  EXPECT_EQ(photo.width * 3, photo.height * 4) << "the aspect ratio stays";
  model::RgbaImage decoded;
  ASSERT_TRUE(render::decode_jpeg(photo.jpeg, 4096, decoded, error)) << error;
  EXPECT_EQ(decoded.width, photo.width);
}

TEST(PhotoDownsizer, TheAstronautPortraitFitsAtGoodQuality) {
  std::vector<std::uint8_t> png;
  std::string error;
  ASSERT_TRUE(model::read_file(test::test_photo("astronaut.png"), 8 << 20, png, error))
      << error;
  DownsizedPhoto photo;
  ASSERT_TRUE(downsize_photo(png, photo, error)) << error;
  EXPECT_EQ(photo.width, 512) << "a photo that already fits keeps its size";
  EXPECT_GE(photo.quality, 60);
  EXPECT_LE(photo.jpeg.size(), kTargetUploadBytes + kTargetUploadBytes / 10);
}

TEST(PhotoDownsizer, ShrinkAveragesAreas) {
  model::RgbaImage stripes(4, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) std::fill_n(stripes.at(x, y), 4, static_cast<std::uint8_t>(x % 2 ? 200 : 0));
  const model::RgbaImage half = shrink_to_fit(stripes, 2);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 1);
  EXPECT_EQ(half.at(0, 0)[0], 100);
  EXPECT_EQ(half.at(1, 0)[0], 100);
}

TEST(PhotoDownsizer, SaysWhatIsWrongWithAFileThatIsNoPhoto) {
  const std::vector<std::uint8_t> text = {'h', 'e', 'l', 'l', 'o'};
  DownsizedPhoto photo;
  std::string error;
  EXPECT_FALSE(downsize_photo(text, photo, error));
  EXPECT_NE(error.find("not a JPEG, PNG or WebP photo"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::client
