#include "image_inspection.hpp"

#include <cstdlib>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

namespace fw::photo {
namespace {

std::vector<std::uint8_t> encoded(int width, int height, const char* extension, int webp_quality = 80) {
  std::vector<uchar> bytes;
  cv::imencode(extension, cv::Mat(height, width, CV_8UC3, cv::Scalar(10, 20, 30)), bytes,
               {cv::IMWRITE_WEBP_QUALITY, webp_quality});
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
  const auto gif = std::string("GIF89a") + std::string(20, '\0');
  EXPECT_FALSE(inspect_photo({reinterpret_cast<const std::uint8_t*>(gif.data()), gif.size()}, error));
  EXPECT_EQ(error.code, PrepErrorCode::unsupported_format);
  EXPECT_NE(error.message.find("GIF image; facewire reads JPEG, PNG and WebP"), std::string::npos) << error.message;
}

// WebP, lossy and lossless, as OpenCV writes them: its size from the first
// chunk, and a file cut short is truncated.
TEST(ImageInspection, ReadsWebPHeadersAndFindsTruncation) {
  for (const int quality : {80, 101}) {  // above 100: lossless (VP8L)
    SCOPED_TRACE(quality);
    const auto webp = encoded(37, 23, ".webp", quality);
    PrepError error;
    const auto header = inspect_photo(webp, error);
    ASSERT_TRUE(header.has_value()) << error.message;
    EXPECT_EQ(header->format, PhotoFormat::webp);
    EXPECT_EQ(header->width, 37);
    EXPECT_EQ(header->height, 23);
    EXPECT_FALSE(inspect_photo(std::span(webp).first(webp.size() - 1), error).has_value());
    EXPECT_EQ(error.code, PrepErrorCode::truncated) << error.message;
  }
}

// A restart marker has no length: libjpeg steps over its two bytes alone.
TEST(ImageInspection, ReadsAJpegWithARestartMarkerBeforeItsFrame) {
  auto jpeg = encoded(64, 48, ".jpg");
  const std::uint8_t restart[] = {0xFF, 0xD0};
  jpeg.insert(jpeg.begin() + 2, std::begin(restart), std::end(restart));
  PrepError error;
  const auto header = inspect_photo(jpeg, error);
  ASSERT_TRUE(header.has_value()) << error.message;
  EXPECT_EQ(header->width, 64);
  EXPECT_EQ(header->height, 48);
}

// Read as a segment with a length, a restart marker let the check skip the
// 8192x8192 frame header libjpeg reads and take a 16x16 one hidden in an
// APP0 segment instead (tests/fuzz/photo_header_fuzz, which asks libjpeg
// too, flags this file).
TEST(ImageInspection, ARestartMarkerDoesNotHideABomb) {
  const auto frame = [](std::uint8_t size_high) {
    return std::vector<std::uint8_t>{0xFF, 0xC0, 0x00, 0x11, 0x08, size_high, 0x00, size_high, 0x00, 3,
                                     1,    0x22, 0,    2,    0x11, 1,         3,    0x11,      1};
  };
  std::vector<std::uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xD0, 0x00, 25};  // "length" 25 lands in the APP0
  const auto big = frame(0x20), small = frame(0x00);
  jpeg.insert(jpeg.end(), big.begin(), big.end());
  jpeg.insert(jpeg.end(), {0xFF, 0xE0, 0x00, 21});
  jpeg.insert(jpeg.end(), small.begin(), small.end());
  jpeg[jpeg.size() - 13] = 16;  // the hidden frame: 16 x 16
  jpeg[jpeg.size() - 11] = 16;
  jpeg.insert(jpeg.end(), {0xFF, 0xDA, 0x00, 0x0C, 3, 1, 0x00, 2, 0x11, 3, 0x11, 0x00, 0x3F, 0x00});
  jpeg.insert(jpeg.end(), 20, 0x00);
  jpeg.insert(jpeg.end(), {0xFF, 0xD9});
  PrepError error;
  const auto header = inspect_photo(jpeg, error);
  EXPECT_FALSE(header.has_value()) << "read as " << header->width << "x" << header->height;
}

// A server's own pixel limit, lower than the decoder's: read from the
// header like the decoder's, and named in the message for the person.
TEST(ImageInspection, ALowerPixelLimitIsReadFromTheHeaderAndNamed) {
  PrepError error;
  const auto small = encoded(300, 200, ".png");
  EXPECT_TRUE(inspect_photo(small, error, 60000).has_value()) << "exactly at the limit: " << error.message;
  EXPECT_FALSE(inspect_photo(small, error, 59999).has_value());
  EXPECT_EQ(error.code, PrepErrorCode::too_many_pixels);
  EXPECT_NE(error.message.find("300x200 pixels; at most 59999 pixels"), std::string::npos) << error.message;
  EXPECT_FALSE(inspect_photo(encoded(2000, 1001, ".jpg"), error, 2000000).has_value());
  EXPECT_NE(error.message.find("2000x1001 pixels; at most 2 megapixels"), std::string::npos) << error.message;
  EXPECT_NE(error.message.find("scale it down"), std::string::npos) << error.message;
}

}  // namespace
}  // namespace fw::photo
