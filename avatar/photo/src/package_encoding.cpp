#include "package_encoding.hpp"

#include <opencv2/imgcodecs.hpp>

namespace fw::photo {

model::PackageImage encode_webp(const cv::Mat& image, int quality) {
  model::PackageImage out;
  out.type = "image/webp";
  std::vector<uchar> bytes;
  cv::imencode(".webp", image, bytes, {cv::IMWRITE_WEBP_QUALITY, quality});
  out.bytes.assign(bytes.begin(), bytes.end());
  return out;
}

}  // namespace fw::photo
