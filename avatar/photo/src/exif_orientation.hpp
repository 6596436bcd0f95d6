#pragma once
// A JPEG's EXIF orientation: cameras store the sensor's rows as they were and
// write which way is up in an Exif tag, so a photo taken upright on its side
// arrives turned by 90 degrees until the tag is applied.
#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

namespace fw::photo {

/// The orientation tag (0x0112) in an APP1 marker's payload ("Exif\0\0" then
/// a TIFF header and IFD0): 1..8 as EXIF numbers them, 1 (as stored) when
/// the payload is not Exif, is damaged or has no such tag.
int exif_orientation(std::span<const std::uint8_t> app1_payload);

/// Turns `image` upright for an EXIF orientation (2..8 flip and/or rotate,
/// anything else leaves it as it is).
void turn_upright(cv::Mat& image, int orientation);

}  // namespace fw::photo
