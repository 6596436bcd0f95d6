#include "decode_photo.hpp"

#include <opencv2/imgcodecs.hpp>

namespace fw::photo {

std::optional<cv::Mat> decode_photo(std::span<const std::uint8_t> bytes, PrepError& error) {
  cv::Mat image;
  try {
    // IMREAD_COLOR applies the EXIF orientation and expands grayscale.
    const cv::Mat wrapped(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(bytes.data()));
    image = cv::imdecode(wrapped, cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    error = {PrepErrorCode::undecodable, std::string("the image cannot be decoded (") + e.err + "); the file may be damaged"};
    return std::nullopt;
  }
  if (image.empty()) {
    error = {PrepErrorCode::undecodable, "the image cannot be decoded; the file may be damaged"};
    return std::nullopt;
  }
  return image;
}

}  // namespace fw::photo
