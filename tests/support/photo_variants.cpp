#include "photo_variants.hpp"

#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include "test_paths.hpp"

namespace fw::test {
namespace {

PhotoVariant rotated(const cv::Mat& original, double degrees) {
  const cv::Point2f centre(original.cols / 2.0f, original.rows / 2.0f);
  const cv::Mat m = cv::getRotationMatrix2D(centre, degrees, 1.0);
  PhotoVariant v{"rotated " + std::to_string(static_cast<int>(degrees)) + " degrees", {}, nullptr};
  cv::warpAffine(original, v.image, m, original.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  v.transform = [m](glm::vec2 p) {
    return glm::vec2(m.at<double>(0, 0) * p.x + m.at<double>(0, 1) * p.y + m.at<double>(0, 2),
                     m.at<double>(1, 0) * p.x + m.at<double>(1, 1) * p.y + m.at<double>(1, 2));
  };
  return v;
}

PhotoVariant placed(const cv::Mat& original, const std::string& name, cv::Size canvas, double scale, cv::Point at) {
  PhotoVariant v{name, cv::Mat(canvas, CV_8UC3, cv::Scalar(128, 128, 128)), nullptr};
  cv::Mat scaled;
  cv::resize(original, scaled, cv::Size(), scale, scale, scale < 1 ? cv::INTER_AREA : cv::INTER_CUBIC);
  scaled.copyTo(v.image(cv::Rect(at, scaled.size())));
  // Pixel centres: original pixel i covers [i, i+1), its centre maps to (i + 0.5) * scale.
  v.transform = [scale, at](glm::vec2 p) {
    return glm::vec2((p.x + 0.5f) * scale - 0.5f + at.x, (p.y + 0.5f) * scale - 0.5f + at.y);
  };
  return v;
}

}  // namespace

std::string astronaut_path() {
  return test_photo("astronaut.png");
}

cv::Mat load_astronaut() { return cv::imread(astronaut_path(), cv::IMREAD_COLOR); }

std::vector<PhotoVariant> standard_variants(const cv::Mat& original) {
  std::vector<PhotoVariant> variants;
  variants.push_back(rotated(original, 15.0));
  const int width = original.cols;
  PhotoVariant mirror{"mirrored", {}, [width](glm::vec2 p) { return glm::vec2(static_cast<float>(width) - 1 - p.x, p.y); }, true};
  cv::flip(original, mirror.image, 1);
  variants.push_back(std::move(mirror));
  variants.push_back(placed(original, "scaled by 0.5", cv::Size(original.cols / 2, original.rows / 2), 0.5, {0, 0}));
  PhotoVariant dark{"darkened", {}, [](glm::vec2 p) { return p; }};
  original.convertTo(dark.image, -1, 0.45, 0);
  variants.push_back(std::move(dark));
  PhotoVariant gray{"grayscale", {}, [](glm::vec2 p) { return p; }};
  cv::cvtColor(original, gray.image, cv::COLOR_BGR2GRAY);
  variants.push_back(std::move(gray));  // single-channel: encoded as a grayscale PNG
  variants.push_back(placed(original, "padded into a large canvas", cv::Size(1600, 1200), 1.0, {700, 500}));
  return variants;
}

std::vector<PhotoVariant> roll_variants(const cv::Mat& original) {
  std::vector<PhotoVariant> variants;
  for (const double degrees : {45.0, 90.0, 180.0}) variants.push_back(rotated(original, degrees));
  return variants;
}

std::vector<PhotoVariant> large_variants(const cv::Mat& original) {
  std::vector<PhotoVariant> variants;
  for (PhotoVariant v : standard_variants(original)) {
    const cv::Mat source = v.image.channels() == 1 ? [&] { cv::Mat c; cv::cvtColor(v.image, c, cv::COLOR_GRAY2BGR); return c; }() : v.image;
    const double fit = 1280.0 / source.rows;
    PhotoVariant large = placed(source, v.name + " at 1920x1280", cv::Size(1920, 1280), fit,
                                {(1920 - static_cast<int>(source.cols * fit)) / 2, 0});
    if (source.cols * fit > 1920) continue;  // too wide for the canvas at that height
    const auto inner = v.transform, outer = large.transform;
    large.transform = [inner, outer](glm::vec2 p) { return outer(inner(p)); };
    large.mirrored = v.mirrored;
    variants.push_back(std::move(large));
  }
  return variants;
}

std::vector<std::uint8_t> encode(const cv::Mat& image, const std::string& extension) {
  std::vector<uchar> bytes;
  cv::imencode(extension, image, bytes);
  return {bytes.begin(), bytes.end()};
}

}  // namespace fw::test
