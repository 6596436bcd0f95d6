#pragma once
// The person's skin tone, for procedural parts (ears, placeholders) that
// should match the photo.
#include <array>
#include <cstdint>

#include <opencv2/core.hpp>

#include "fw/model/vascular_masks.hpp"

namespace fw::photo {

/// sRGB skin tone: the per-channel median of the face texture (BGR) where
/// the forehead and cheek masks are strong.
std::array<std::uint8_t, 3> estimate_skin_tone(const cv::Mat& texture,
                                               const std::array<model::Mask, model::kMaskRegionCount>& masks,
                                               int mask_size);

}  // namespace fw::photo
