#pragma once
// A colour texture's mip levels, made once on upload and stored so that
// llvmpipe samples them cheaply. Colour textures hold the square root of
// linear light in eight bits: llvmpipe filters 8-bit textures on a fast
// integer path, where it decodes an sRGB texture's every texel it reads
// (eight for each trilinear sample) on its slower float path, and 16-bit
// linear texels take that path too. The square root keeps the darks' steps
// (a step is finer than sRGB's near black, about as fine near white); the
// shader squares what it samples. The levels are averaged in linear light,
// so a texture seen smaller shows the average of its light, as before.
#include <cstdint>
#include <vector>

#include "fw/model/image.hpp"

namespace fw::render {

/// One level: RGBA bytes, bottom row first (texture v runs up).
struct MipLevel {
  int width = 0, height = 0;
  std::vector<std::uint8_t> texels;
};

/// Every mip level of `srgb` (sRGB-encoded colour, straight alpha, rows top
/// first) down to 1x1, each level half the last (rounded down, at least 1),
/// as square-root-of-light colour and linear alpha. Empty for an empty image.
std::vector<MipLevel> square_root_light_mipmaps(const model::RgbaImage& srgb);

}  // namespace fw::render
