#pragma once
// Decoding the images an avatar package carries (WebP, PNG), with bounds
// checked before any pixel is decoded.
#include <cstdint>
#include <span>
#include <string>

#include "fw/model/image.hpp"

namespace fw::render {

/// Decodes a WebP or PNG image (told apart by their signatures) to RGBA.
/// @param[in]  bytes     the encoded image
/// @param[in]  max_side  largest width or height accepted
/// @param[out] image     the pixels, rows top down
/// @param[out] error     what is wrong, on failure
bool decode_image(std::span<const std::uint8_t> bytes, int max_side, model::RgbaImage& image, std::string& error);

}  // namespace fw::render
