#pragma once
// The generic face's procedural textures (eye holes, closed lids, blood
// masks) with the skin repainted, for render tests that need to know what
// colour every skin point has; and sRGB decoding to compare light.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "fw/render/avatar_appearance.hpp"

namespace fw::test {

inline float to_linear(std::uint8_t encoded) {
  const float v = encoded / 255.0f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

/// The skin painted by `paint(x, y)` (an sRGB colour per texel); its
/// textures hold `light` (a photo's by default: shown as they are at rest).
template <typename Paint>
render::AvatarAppearance painted_face(Paint paint, model::TextureLight light = model::TextureLight::photo) {
  render::AvatarAppearance face = render::generic_appearance(model::Appearance{});
  face.textures.light = light;
  model::RgbaImage& skin = face.textures.skin;
  for (int y = 0; y < skin.height; ++y)
    for (int x = 0; x < skin.width; ++x) {
      const glm::u8vec3 rgb = paint(x, y);
      std::uint8_t* p = skin.at(x, y);
      p[0] = rgb.r, p[1] = rgb.g, p[2] = rgb.b;
    }
  return face;
}

inline render::AvatarAppearance flat_face(glm::u8vec3 rgb, model::TextureLight light = model::TextureLight::photo) {
  return painted_face([rgb](int, int) { return rgb; }, light);
}

}  // namespace fw::test
