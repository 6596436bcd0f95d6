#include "demo_faces.hpp"

#include <array>

#include "fw/model/generic_face.hpp"
#include "fw/model/procedural_texture.hpp"
#include "fw/model/vascular_masks.hpp"
#include "package_images.hpp"

namespace fw::server {
namespace {

model::Appearance look_for(std::uint32_t index) {
  // Three distinct people first (light, dark, olive skin; blue, brown,
  // green eyes; brown, black, auburn hair), then mixtures of them.
  // Named fields: Appearance has gained fields before (the sclera), and a
  // positional list silently fills the wrong one (lip colour in the whites).
  static const std::array<model::Appearance, 3> kLooks = {{
      {.skin = {0.90f, 0.72f, 0.62f}, .hair = {0.30f, 0.20f, 0.12f}, .iris = {0.30f, 0.48f, 0.70f},
       .lips = {0.75f, 0.42f, 0.42f}},
      {.skin = {0.45f, 0.30f, 0.22f}, .hair = {0.06f, 0.05f, 0.05f}, .iris = {0.28f, 0.17f, 0.08f},
       .lips = {0.45f, 0.25f, 0.24f}},
      {.skin = {0.76f, 0.58f, 0.42f}, .hair = {0.48f, 0.20f, 0.10f}, .iris = {0.30f, 0.50f, 0.30f},
       .lips = {0.68f, 0.36f, 0.34f}},
  }};
  if (index < kLooks.size()) return kLooks[index];
  const auto& a = kLooks[index % 3];
  const auto& b = kLooks[(index / 3 + 1) % 3];
  const float t = static_cast<float>((index * 37) % 100) / 100.0f;
  return {.skin = a.skin * (1 - t) + b.skin * t, .hair = b.hair, .iris = a.iris * t + b.iris * (1 - t), .lips = a.lips};
}

std::array<std::uint8_t, 3> to_srgb8(const glm::vec3& c) {
  return {static_cast<std::uint8_t>(c.r * 255 + 0.5f), static_cast<std::uint8_t>(c.g * 255 + 0.5f),
          static_cast<std::uint8_t>(c.b * 255 + 0.5f)};
}

}  // namespace

std::vector<std::uint8_t> make_demo_package(std::uint32_t index) {
  constexpr int kQuality = 80;
  constexpr int kMaskSize = 64;
  const model::GenericFace& face = model::generic_face();
  const model::Appearance look = look_for(index);
  model::AvatarPackage package;
  package.generic_face_version = face.version;
  // The generic face is its own fit.
  package.fitted_vertices.reserve(face.skin.positions.size());
  for (const auto& p : face.skin.positions) package.fitted_vertices.emplace_back(p.x, p.y);
  for (std::size_t i = 0; i < model::kLandmarkCount; ++i) {
    const auto& p = face.skin.positions[face.landmark_vertices[i]];
    package.landmarks[i] = {p.x, p.y};
  }
  package.skin_tone = to_srgb8(look.skin);
  package.iris_colour = to_srgb8(look.iris);
  // Procedural textures are the surface's own colour: a renderer lights them.
  package.texture_light = model::TextureLight::albedo;
  const model::RgbaImage skin = model::make_skin_texture(face, look, 256);
  package.face_texture = encode_package_image(skin, kQuality);
  package.closed_lid = encode_package_image(model::make_skin_texture(face, look, 128, /*eye_holes=*/false), kQuality);
  package.closed_lid_rect = {0.0f, 0.0f, 1.0f, 1.0f};
  package.eye = encode_package_image(model::make_eye_texture(face.eyes[0], look, 64), kQuality);
  package.mouth = encode_package_image(model::make_mouth_texture(), kQuality);
  const auto masks = model::pack_region_masks(
      model::render_region_masks([](glm::vec2 p) { return p; }, face.texture_frame, kMaskSize), kMaskSize);
  package.colour_masks_a = encode_package_image(masks[0], 100);
  package.colour_masks_b = encode_package_image(masks[1], 100);
  package.preview = encode_package_image(model::make_skin_texture(face, look, 64), 60);
  return model::serialize_avatar_package(package);
}

}  // namespace fw::server
