#include "package_images.hpp"

#include <algorithm>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <webp/encode.h>

#include "fw/render/image_codec.hpp"

namespace fw::server {

model::PackageImage encode_package_image(const model::RgbaImage& image, int quality) {
  // Fully opaque pixels get no alpha plane: libwebp leaves it out itself.
  std::uint8_t* out = nullptr;
  const std::size_t size = WebPEncodeRGBA(image.pixels.data(), image.width, image.height, image.width * 4,
                                          static_cast<float>(std::clamp(quality, 1, 100)), &out);
  model::PackageImage encoded;
  encoded.type = "image/webp";
  if (out) encoded.bytes.assign(out, out + size);
  WebPFree(out);
  return encoded;
}

std::optional<model::PackageImage> shrink_package_image(const model::PackageImage& image, int max_side, int quality) {
  if (image.bytes.empty()) return model::PackageImage{};  // an absent member stays absent
  // Package members are bounded by the package's own size limit; this bound
  // only keeps a hostile header from asking for a huge allocation.
  constexpr int kLargestMember = 8192;
  model::RgbaImage decoded;
  std::string error;
  if (!render::decode_image(image.bytes, kLargestMember, decoded, error)) return std::nullopt;
  const double scale = std::min(1.0, static_cast<double>(max_side) / std::max(decoded.width, decoded.height));
  const cv::Mat pixels(decoded.height, decoded.width, CV_8UC4, decoded.pixels.data());
  model::RgbaImage small(std::max(1, static_cast<int>(decoded.width * scale + 0.5)),
                         std::max(1, static_cast<int>(decoded.height * scale + 0.5)));
  cv::Mat small_pixels(small.height, small.width, CV_8UC4, small.pixels.data());
  cv::resize(pixels, small_pixels, small_pixels.size(), 0, 0, cv::INTER_AREA);
  return encode_package_image(small, quality);
}

}  // namespace fw::server
