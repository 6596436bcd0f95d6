#pragma once
// The three photo formats facewire accepts, decoded straight through
// libjpeg-turbo, libpng and libwebp to what OpenCV's imdecode(IMREAD_COLOR)
// gave, pixel for pixel: 8-bit BGR, alpha dropped, grey in three equal
// channels, a JPEG turned upright by its EXIF orientation. OpenCV's imgcodecs
// would do the same, but it brings some 120 libraries (GDAL, GDCM, OpenEXR and
// their dependencies) into every process that links it, a tenth of a second
// at each start, and decoders for formats facewire refuses anyway.
#include <cstdint>
#include <optional>
#include <span>

#include <opencv2/core.hpp>

#include "fw/photo/prep_error.hpp"

namespace fw::photo {

/// Each decodes one format; nullopt and `error` (too_many_pixels past
/// kMaxPhotoPixels, read from the decoder's own header before any pixel is,
/// else undecodable) when it cannot.
std::optional<cv::Mat> decode_jpeg_photo(std::span<const std::uint8_t> bytes, PrepError& error);
std::optional<cv::Mat> decode_png_photo(std::span<const std::uint8_t> bytes, PrepError& error);
std::optional<cv::Mat> decode_webp_photo(std::span<const std::uint8_t> bytes, PrepError& error);

/// Whether a width x height image is within kMaxPhotoPixels; `error` says by
/// how much it is not. A second guard behind the header check, for the
/// dimensions the decoder itself reads.
bool decodable_size(std::uint64_t width, std::uint64_t height, PrepError& error);

}  // namespace fw::photo
