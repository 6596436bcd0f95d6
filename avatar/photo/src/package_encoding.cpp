#include "package_encoding.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>
#include <webp/encode.h>

namespace fw::photo {

model::PackageImage encode_webp(const cv::Mat& image, int quality) {
  cv::Mat colour = image;
  if (image.channels() == 1) cv::cvtColor(image, colour, cv::COLOR_GRAY2BGR);
  const bool alpha = colour.channels() == 4, lossless = quality > 100;
  const float lossy_quality = static_cast<float>(std::max(quality, 1));
  const int stride = static_cast<int>(colour.step);
  std::uint8_t* out = nullptr;
  std::size_t size = 0;
  if (lossless)
    size = alpha ? WebPEncodeLosslessBGRA(colour.ptr(), colour.cols, colour.rows, stride, &out)
                 : WebPEncodeLosslessBGR(colour.ptr(), colour.cols, colour.rows, stride, &out);
  else
    size = alpha ? WebPEncodeBGRA(colour.ptr(), colour.cols, colour.rows, stride, lossy_quality, &out)
                 : WebPEncodeBGR(colour.ptr(), colour.cols, colour.rows, stride, lossy_quality, &out);
  model::PackageImage encoded;
  encoded.type = "image/webp";
  if (out) encoded.bytes.assign(out, out + size);
  WebPFree(out);
  return encoded;
}

}  // namespace fw::photo
