#include <webp/decode.h>

#include "photo_decoders.hpp"

namespace fw::photo {

std::optional<cv::Mat> decode_webp_photo(std::span<const std::uint8_t> bytes, PrepError& error) {
  int width = 0, height = 0;
  if (!WebPGetInfo(bytes.data(), bytes.size(), &width, &height)) {
    error = {PrepErrorCode::undecodable, "the image cannot be decoded (not a valid WebP); the file may be damaged"};
    return std::nullopt;
  }
  if (!decodable_size(static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height), error)) return std::nullopt;
  cv::Mat image(height, width, CV_8UC3);
  // A WebP with alpha decodes to its colour alone, as OpenCV's IMREAD_COLOR did.
  if (!WebPDecodeBGRInto(bytes.data(), bytes.size(), image.data, image.total() * 3, static_cast<int>(image.step))) {
    error = {PrepErrorCode::undecodable, "the image cannot be decoded (not a valid WebP); the file may be damaged"};
    return std::nullopt;
  }
  return image;
}

}  // namespace fw::photo
