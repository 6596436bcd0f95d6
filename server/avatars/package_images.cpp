#include "package_images.hpp"

#include <algorithm>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace fw::server {
namespace {

model::PackageImage encode_mat(const cv::Mat& bgra, int quality) {
  model::PackageImage out;
  out.type = "image/webp";
  cv::imencode(".webp", bgra, out.bytes, {cv::IMWRITE_WEBP_QUALITY, quality});
  return out;
}

}  // namespace

model::PackageImage encode_package_image(const model::RgbaImage& image, int quality) {
  cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.pixels.data()));
  cv::Mat bgra;
  cv::cvtColor(rgba, bgra, cv::COLOR_RGBA2BGRA);
  return encode_mat(bgra, quality);
}

std::optional<model::PackageImage> shrink_package_image(const model::PackageImage& image, int max_side, int quality) {
  if (image.bytes.empty()) return model::PackageImage{};  // an absent member stays absent
  const cv::Mat encoded(1, static_cast<int>(image.bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(image.bytes.data()));
  const cv::Mat decoded = cv::imdecode(encoded, cv::IMREAD_UNCHANGED);
  if (decoded.empty()) return std::nullopt;
  const double scale = std::min(1.0, static_cast<double>(max_side) / std::max(decoded.cols, decoded.rows));
  cv::Mat small;
  cv::resize(decoded, small, cv::Size(std::max(1, static_cast<int>(decoded.cols * scale + 0.5)),
                                      std::max(1, static_cast<int>(decoded.rows * scale + 0.5))),
             0, 0, cv::INTER_AREA);
  return encode_mat(small, quality);
}

}  // namespace fw::server
