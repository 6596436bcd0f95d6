#include "fw/render/png.hpp"

#include <filesystem>

#include <gtest/gtest.h>
#include <png.h>

namespace fw::render {
namespace {

TEST(Png, WritesAnImageThatReadsBackTheSame) {
  model::RgbaImage image(5, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<std::uint8_t>(i * 7);
  const auto path = std::filesystem::temp_directory_path() / "facewire_png_test.png";
  std::string error;
  ASSERT_TRUE(write_png(image, path, error)) << error;

  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, path.c_str()));
  png.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(png));
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr));
  EXPECT_EQ(png.width, 5u);
  EXPECT_EQ(png.height, 3u);
  EXPECT_EQ(pixels, image.pixels);
  std::filesystem::remove(path);
}

TEST(Png, SaysWhyItCannotWrite) {
  std::string error;
  EXPECT_FALSE(write_png(model::RgbaImage(4, 4), "/nonexistent-dir/x.png", error));
  EXPECT_NE(error.find("/nonexistent-dir/x.png"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::render
