#include "photo_decoders.hpp"

#include <algorithm>
#include <cstdio>  // before jpeglib.h, which uses FILE
#include <cstdlib>

#include <gtest/gtest.h>
#include <jpeglib.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "decode_photo.hpp"
#include "photo_variants.hpp"

namespace fw::photo {
namespace {

// OpenCV's imdecode(IMREAD_COLOR), which facewire's photos went through
// before, is the observer here: the direct decoders must give its pixels.
cv::Mat opencv_decode(const std::vector<std::uint8_t>& bytes) { return cv::imdecode(bytes, cv::IMREAD_COLOR); }

// Inspected first, as every photo is before it is decoded.
std::optional<cv::Mat> inspect_and_decode(const std::vector<std::uint8_t>& bytes, PrepError& error) {
  const auto header = inspect_photo(bytes, error);
  if (!header) return std::nullopt;
  return decode_photo(bytes, *header, error);
}

void expect_same_pixels(const std::vector<std::uint8_t>& bytes, const std::string& what) {
  PrepError error;
  const auto ours = inspect_and_decode(bytes, error);
  ASSERT_TRUE(ours.has_value()) << what << ": " << error.message;
  const cv::Mat reference = opencv_decode(bytes);
  ASSERT_FALSE(reference.empty()) << what;
  ASSERT_EQ(ours->type(), CV_8UC3) << what;
  ASSERT_EQ(ours->size(), reference.size()) << what;
  EXPECT_EQ(cv::norm(*ours, reference, cv::NORM_INF), 0.0) << what << " differs from OpenCV's decoding";
}

// A crop of the portrait (a real photo's texture) in the given OpenCV type.
cv::Mat portrait_crop(int type) {
  const cv::Mat bgr = test::load_astronaut()(cv::Rect(100, 40, 301, 257)).clone();  // odd sizes
  cv::Mat out;
  switch (type) {
    case CV_8UC1: cv::cvtColor(bgr, out, cv::COLOR_BGR2GRAY); break;
    case CV_8UC4:
      cv::cvtColor(bgr, out, cv::COLOR_BGR2BGRA);
      for (int y = 0; y < out.rows; ++y)
        for (int x = 0; x < out.cols; ++x) out.at<cv::Vec4b>(y, x)[3] = static_cast<std::uint8_t>((x * 7 + y) % 256);
      break;
    case CV_16UC3: bgr.convertTo(out, CV_16UC3, 257.0); out += cv::Scalar(91, 3, 200); break;
    default: out = bgr;
  }
  return out;
}

std::vector<std::uint8_t> encode(const cv::Mat& image, const char* extension, std::vector<int> parameters = {}) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes, parameters)) << extension;
  return bytes;
}

TEST(PhotoDecoders, JpegComesOutAsOpenCvDecodedIt) {
  expect_same_pixels(encode(portrait_crop(CV_8UC3), ".jpg"), "colour JPEG");
  expect_same_pixels(encode(portrait_crop(CV_8UC1), ".jpg"), "grey JPEG");
  expect_same_pixels(encode(portrait_crop(CV_8UC3), ".jpg", {cv::IMWRITE_JPEG_PROGRESSIVE, 1}), "progressive JPEG");
  expect_same_pixels(encode(portrait_crop(CV_8UC3), ".jpg", {cv::IMWRITE_JPEG_QUALITY, 40}), "JPEG at quality 40");
}

// A CMYK JPEG as Adobe's tools write it (inks inverted, an Adobe marker),
// which cv::imencode cannot make: libjpeg writes it from the portrait.
std::vector<std::uint8_t> adobe_cmyk_jpeg(const cv::Mat& bgr) {
  jpeg_compress_struct info{};
  jpeg_error_mgr errors{};
  info.err = jpeg_std_error(&errors);
  jpeg_create_compress(&info);
  unsigned char* out = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&info, &out, &size);
  info.image_width = static_cast<JDIMENSION>(bgr.cols);
  info.image_height = static_cast<JDIMENSION>(bgr.rows);
  info.input_components = 4;
  info.in_color_space = JCS_CMYK;
  jpeg_set_defaults(&info);
  info.write_Adobe_marker = TRUE;
  jpeg_start_compress(&info, TRUE);
  std::vector<std::uint8_t> row(static_cast<std::size_t>(bgr.cols) * 4);
  while (info.next_scanline < info.image_height) {
    const auto* pixel = bgr.ptr<cv::Vec3b>(static_cast<int>(info.next_scanline));
    for (int x = 0; x < bgr.cols; ++x) {
      // Inverted inks: 255 is no ink. Black takes what the three share.
      const int k = std::max({pixel[x][0], pixel[x][1], pixel[x][2]});
      row[4 * x + 0] = pixel[x][2];
      row[4 * x + 1] = pixel[x][1];
      row[4 * x + 2] = pixel[x][0];
      row[4 * x + 3] = static_cast<std::uint8_t>(k);
    }
    JSAMPROW rows[1] = {row.data()};
    jpeg_write_scanlines(&info, rows, 1);
  }
  jpeg_finish_compress(&info);
  std::vector<std::uint8_t> bytes(out, out + size);
  jpeg_destroy_compress(&info);
  std::free(out);
  return bytes;
}

TEST(PhotoDecoders, AdobeCmykJpegComesOutAsOpenCvDecodedIt) {
  expect_same_pixels(adobe_cmyk_jpeg(portrait_crop(CV_8UC3)), "Adobe CMYK JPEG");
}

TEST(PhotoDecoders, PngComesOutAsOpenCvDecodedIt) {
  expect_same_pixels(encode(portrait_crop(CV_8UC3), ".png"), "colour PNG");
  expect_same_pixels(encode(portrait_crop(CV_8UC1), ".png"), "grey PNG");
  expect_same_pixels(encode(portrait_crop(CV_8UC4), ".png"), "PNG with alpha");
  expect_same_pixels(encode(portrait_crop(CV_16UC3), ".png"), "16-bit PNG");
  cv::Mat bits = portrait_crop(CV_8UC1) > 128;
  expect_same_pixels(encode(bits, ".png", {cv::IMWRITE_PNG_BILEVEL, 1}), "one-bit PNG");
}

TEST(PhotoDecoders, WebpComesOutAsOpenCvDecodedIt) {
  expect_same_pixels(encode(portrait_crop(CV_8UC3), ".webp", {cv::IMWRITE_WEBP_QUALITY, 80}), "lossy WebP");
  expect_same_pixels(encode(portrait_crop(CV_8UC3), ".webp", {cv::IMWRITE_WEBP_QUALITY, 101}), "lossless WebP");
  expect_same_pixels(encode(portrait_crop(CV_8UC4), ".webp", {cv::IMWRITE_WEBP_QUALITY, 90}), "WebP with alpha");
}

TEST(PhotoDecoders, TheDecodersOwnHeaderReadingRefusesPastFortyMegapixels) {
  // The header check stops these first; the decoders check again with the
  // dimensions they read themselves.
  const std::vector<std::uint8_t> huge = encode(cv::Mat::zeros(6000, 7000, CV_8UC1), ".png");
  PrepError error;
  EXPECT_FALSE(decode_png_photo(huge, error).has_value());
  EXPECT_EQ(error.code, PrepErrorCode::too_many_pixels);
  EXPECT_NE(error.message.find("scale it down"), std::string::npos) << error.message;
}

TEST(PhotoDecoders, ADamagedPhotoIsUndecodableWithAReason) {
  // Whole files (inspect_photo passes them) whose image data is garbled.
  // PNG carries checksums and must be refused; JPEG and WebP carry none, and
  // their decoders may draw garbage instead, as OpenCV's did.
  for (const char* extension : {".jpg", ".png", ".webp"}) {
    std::vector<std::uint8_t> bytes = encode(portrait_crop(CV_8UC3), extension);
    // Sixteen bytes in the middle, one bit each; none becomes or follows a
    // JPEG marker's 0xFF, so the file still parses to its end.
    for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i)
      if (bytes[i] < 0xfe && bytes[i - 1] != 0xff) bytes[i] ^= 0x01;
    PrepError error;
    ASSERT_TRUE(inspect_photo(bytes, error).has_value()) << extension << ": " << error.message;
    const auto decoded = inspect_and_decode(bytes, error);
    if (std::string(extension) == ".png") {
      EXPECT_FALSE(decoded.has_value()) << "a PNG with a bad checksum decoded";
    }
    if (decoded) continue;
    EXPECT_EQ(error.code, PrepErrorCode::undecodable) << extension;
    EXPECT_NE(error.message.find("damaged"), std::string::npos) << extension << ": " << error.message;
  }
}

}  // namespace
}  // namespace fw::photo
