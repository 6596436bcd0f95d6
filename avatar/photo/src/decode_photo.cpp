#include "decode_photo.hpp"

#include <cstring>

#include "fw/photo/photo_limits.hpp"
#include "photo_decoders.hpp"

namespace fw::photo {

bool decodable_size(std::uint64_t width, std::uint64_t height, PrepError& error) {
  if (width == 0 || height == 0) {
    error = {PrepErrorCode::undecodable, "the image has no pixels; the file may be damaged"};
    return false;
  }
  if (width * height > kMaxPhotoPixels) {
    error = {PrepErrorCode::too_many_pixels,
             "the image is " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than the " +
                 std::to_string(kMaxPhotoPixels / 1000000) + " megapixels accepted: scale it down"};
    return false;
  }
  return true;
}

std::optional<cv::Mat> decode_photo(std::span<const std::uint8_t> bytes, PrepError& error) {
  if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) return decode_jpeg_photo(bytes, error);
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0) return decode_png_photo(bytes, error);
  if (bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 && std::memcmp(bytes.data() + 8, "WEBP", 4) == 0)
    return decode_webp_photo(bytes, error);
  error = {PrepErrorCode::not_an_image, "the file is not a JPEG, PNG or WebP image"};
  return std::nullopt;
}

}  // namespace fw::photo
