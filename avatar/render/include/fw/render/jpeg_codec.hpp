#pragma once
// JPEG in and out (libjpeg-turbo): photos people upload come as JPEG, and
// the thin client re-encodes a downsized photo as JPEG before sending it.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fw/model/image.hpp"

namespace fw::render {

/// Whether `bytes` start with a JPEG signature (SOI marker then another marker).
bool is_jpeg(std::span<const std::uint8_t> bytes);

/// Decodes a baseline or progressive JPEG (grey, RGB or CMYK-free YCbCr) to RGBA.
/// @param[in]  bytes     the encoded image
/// @param[in]  max_side  largest width or height accepted, checked before any pixel is decoded
/// @param[out] image     the pixels, rows top down, alpha 255
/// @param[out] error     what is wrong, on failure
bool decode_jpeg(std::span<const std::uint8_t> bytes, int max_side, model::RgbaImage& image, std::string& error);

/// Encodes `image` (alpha ignored) as a baseline JPEG.
/// @param[in]  image    at least 1x1
/// @param[in]  quality  1 (smallest) .. 100 (best)
/// @param[out] bytes    the JPEG file
/// @param[out] error    what is wrong, on failure
bool encode_jpeg(const model::RgbaImage& image, int quality, std::vector<std::uint8_t>& bytes, std::string& error);

}  // namespace fw::render
