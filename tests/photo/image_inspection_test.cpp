#include "image_inspection.hpp"

#include <cstdlib>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

namespace fw::photo {
namespace {

std::vector<std::uint8_t> encoded(int width, int height, const char* extension) {
  std::vector<uchar> bytes;
  cv::imencode(extension, cv::Mat(height, width, CV_8UC3, cv::Scalar(10, 20, 30)), bytes);
  return {bytes.begin(), bytes.end()};
}

TEST(ImageInspection, ReadsSizeFromPngAndJpegHeaders) {
  PrepError error;
  const auto png = inspect_photo(encoded(37, 21, ".png"), error);
  ASSERT_TRUE(png.has_value()) << error.message;
  EXPECT_EQ(png->format, PhotoFormat::png);
  EXPECT_EQ(png->width, 37);
  EXPECT_EQ(png->height, 21);
  const auto jpeg = inspect_photo(encoded(64, 48, ".jpg"), error);
  ASSERT_TRUE(jpeg.has_value()) << error.message;
  EXPECT_EQ(jpeg->format, PhotoFormat::jpeg);
  EXPECT_EQ(jpeg->width, 64);
  EXPECT_EQ(jpeg->height, 48);
}

TEST(ImageInspection, EveryTruncationOfASmallPngIsCaught) {
  const auto png = encoded(20, 20, ".png");
  for (std::size_t cut = 8; cut < png.size(); ++cut) {
    PrepError error;
    EXPECT_FALSE(inspect_photo(std::span(png).first(cut), error).has_value()) << cut;
  }
}

TEST(ImageInspection, EveryTruncationOfASmallJpegIsCaught) {
  const auto jpeg = encoded(20, 20, ".jpg");
  for (std::size_t cut = 3; cut < jpeg.size(); ++cut) {
    PrepError error;
    EXPECT_FALSE(inspect_photo(std::span(jpeg).first(cut), error).has_value()) << cut;
  }
}

TEST(ImageInspection, NamesOtherFormats) {
  PrepError error;
  static constexpr char kWebp[] = "RIFF\x10\0\0\0WEBPVP8 ";
  const std::string webp(kWebp, sizeof kWebp - 1);
  EXPECT_FALSE(inspect_photo({reinterpret_cast<const std::uint8_t*>(webp.data()), webp.size()}, error));
  EXPECT_EQ(error.code, PrepErrorCode::unsupported_format);
  EXPECT_NE(error.message.find("WebP"), std::string::npos);
}

}  // namespace
}  // namespace fw::photo

namespace fw::photo {
namespace {

// ctest runs this with OPENCV_IO_MAX_IMAGE_PIXELS as facewire-server sets it
// for itself: OpenCV itself refuses what the header check would.
TEST(DecoderPixelLimit, OpenCvRefusesPastFortyMegapixels) {
  ASSERT_NE(std::getenv("OPENCV_IO_MAX_IMAGE_PIXELS"), nullptr);
  std::vector<uchar> bytes;
  cv::imencode(".png", cv::Mat::zeros(6000, 7000, CV_8UC1), bytes);
  bool refused = false;
  try {
    refused = cv::imdecode(bytes, cv::IMREAD_GRAYSCALE).empty();
  } catch (const cv::Exception&) {
    refused = true;
  }
  EXPECT_TRUE(refused) << "42 megapixels decoded despite the limit";
}

}  // namespace
}  // namespace fw::photo
