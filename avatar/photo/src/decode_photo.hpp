#pragma once
#include <cstdint>
#include <optional>
#include <span>

#include <opencv2/core.hpp>

#include "fw/photo/prep_error.hpp"
#include "image_inspection.hpp"

namespace fw::photo {

/// Decodes a photo that inspect_photo passed, by the format it found, to
/// 8-bit BGR, turned upright by its EXIF orientation; grayscale photos come
/// out as three equal channels.
std::optional<cv::Mat> decode_photo(std::span<const std::uint8_t> bytes, const PhotoHeader& header, PrepError& error);

}  // namespace fw::photo
