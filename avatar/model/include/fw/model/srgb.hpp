#pragma once
// sRGB codes and linear light: the transfer the renderers' sRGB textures
// decode with. Averages of colours (mipmaps, smoothing) are taken in linear
// light: averaging the codes darkens every mix (of hair and skin, say).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fw::model {

/// An 8-bit sRGB code as linear light in [0,1].
inline float linear_from_srgb(std::uint8_t code) {
  const float e = static_cast<float>(code) / 255.0f;
  return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
}

/// Linear light (clamped to [0,1]) as the nearest 8-bit sRGB code.
inline std::uint8_t srgb_from_linear(float linear) {
  const float l = std::clamp(linear, 0.0f, 1.0f);
  const float e = l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(e * 255.0f + 0.5f);
}

}  // namespace fw::model
