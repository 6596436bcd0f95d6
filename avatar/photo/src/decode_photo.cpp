#include "decode_photo.hpp"

#include "fw/photo/photo_limits.hpp"
#include "photo_decoders.hpp"

namespace fw::photo {

bool decodable_size(std::uint64_t width, std::uint64_t height, PrepError& error) {
  if (width == 0 || height == 0) {
    error = {PrepErrorCode::undecodable, "the image has no pixels; the file may be damaged"};
    return false;
  }
  if (width * height > kMaxPhotoPixels) {
    // Worded as inspect_photo's refusal, which comes first for any photo whose
    // header and image data agree.
    error = {PrepErrorCode::too_many_pixels, "the photo is " + std::to_string(width) + "x" + std::to_string(height) +
                                                 " pixels; at most " + std::to_string(kMaxPhotoPixels / 1000000) +
                                                 " megapixels is accepted: scale it down"};
    return false;
  }
  return true;
}

std::optional<cv::Mat> decode_photo(std::span<const std::uint8_t> bytes, const PhotoHeader& header, PrepError& error) {
  switch (header.format) {
    case PhotoFormat::jpeg: return decode_jpeg_photo(bytes, error);
    case PhotoFormat::png: return decode_png_photo(bytes, error);
    case PhotoFormat::webp: return decode_webp_photo(bytes, error);
  }
  return std::nullopt;
}

}  // namespace fw::photo
