#include "fw/render/avatar_appearance.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "fw/model/landmark_template.hpp"
#include "fw/model/procedural_texture.hpp"

#include "fw/model/vascular_masks.hpp"
#include "fw/render/image_codec.hpp"

namespace fw::render {
namespace {

// Package textures are 256 or 512 px; anything larger is not one of ours.
constexpr int kMaxTextureSide = 1024;

}  // namespace

bool load_avatar_appearance(const model::AvatarPackage& package, AvatarAppearance& appearance, std::string& error) {
  AvatarAppearance loaded;
  const auto decode = [&](const model::PackageImage& member, const char* name, model::RgbaImage& out) {
    if (decode_image(member.bytes, kMaxTextureSide, out, error)) return true;
    error = std::string("avatar package member ") + name + ": " + error;
    return false;
  };
  FaceTextures& t = loaded.textures;
  const bool eye_layer = !package.eye.bytes.empty();
  if (!decode(package.face_texture, "face_texture", t.skin) || (eye_layer && !decode(package.eye, "eye", t.eye)) ||
      !decode(package.mouth, "mouth", t.mouth) || !decode(package.closed_lid, "closed_lid", t.closed_lid) ||
      !decode(package.colour_masks_a, "colour_masks_a", t.masks_a) ||
      !decode(package.colour_masks_b, "colour_masks_b", t.masks_b))
    return false;
  t.closed_lid_rect = package.closed_lid_rect;
  t.light = package.texture_light;
  loaded.avatar = model::make_avatar_model(model::generic_face(), package.fitted_vertices, package.head_outline);
  appearance = std::move(loaded);
  return true;
}

namespace {

// The closed lids of a procedural face: the skin texture drawn without eye
// holes, cut to the band around the eyes. The band, not the whole texture:
// the shader lays the closed-lid layer where the face has moved to, so a
// whole-texture layer would paint the rest pose over every expression's
// lips and brows while the lids close.
void add_closed_lids(const model::GenericFace& face, const model::Appearance& look, FaceTextures& textures) {
  constexpr int kSize = 512;
  // Model units around the eye corners and lids: enough for the lids, short
  // of the brows (their lower edge is 0.16 above the eye line at the outer
  // ends), which a raised brow would otherwise leave behind as a ghost.
  constexpr glm::vec2 kMargin(0.12f, 0.1f);
  namespace lm = model::landmarks;
  const auto tmpl = model::landmark_template();
  glm::vec2 low(1e9f), high(-1e9f);
  for (int i = lm::kEyeRightBegin; i < lm::kEyeLeftEnd; ++i) {
    low = glm::min(low, tmpl[static_cast<std::size_t>(i)]);
    high = glm::max(high, tmpl[static_cast<std::size_t>(i)]);
  }
  const glm::vec2 uv_low = glm::clamp(face.texture_frame.to_uv(low - kMargin), 0.0f, 1.0f);
  const glm::vec2 uv_high = glm::clamp(face.texture_frame.to_uv(high + kMargin), 0.0f, 1.0f);
  // Whole texels of the full texture (row 0 at the top, uv.y = 1 there).
  const int x0 = static_cast<int>(std::floor(uv_low.x * kSize)), x1 = static_cast<int>(std::ceil(uv_high.x * kSize));
  const int y0 = static_cast<int>(std::floor((1.0f - uv_high.y) * kSize));
  const int y1 = static_cast<int>(std::ceil((1.0f - uv_low.y) * kSize));
  const model::RgbaImage full = model::make_skin_texture(face, look, kSize, /*eye_holes=*/false);
  model::RgbaImage band(x1 - x0, y1 - y0);
  for (int y = y0; y < y1; ++y) std::copy_n(full.at(x0, y), 4 * band.width, band.at(0, y - y0));
  textures.closed_lid = std::move(band);
  textures.closed_lid_rect = {static_cast<float>(x0) / kSize, 1.0f - static_cast<float>(y1) / kSize,
                              static_cast<float>(x1) / kSize, 1.0f - static_cast<float>(y0) / kSize};
}

}  // namespace

AvatarAppearance generic_appearance(const model::Appearance& look) {
  constexpr int kMaskSize = 64;
  AvatarAppearance a;
  a.avatar = model::generic_avatar_model();
  const model::GenericFace& face = a.avatar.face;
  a.textures.light = model::TextureLight::albedo;
  a.textures.skin = model::make_skin_texture(face, look);
  a.textures.eye = model::make_eye_texture(face.eyes[0], look);
  a.textures.mouth = model::make_mouth_texture();
  add_closed_lids(face, look, a.textures);
  const auto masks = model::pack_region_masks(
      model::render_region_masks([](glm::vec2 p) { return p; }, face.texture_frame, kMaskSize), kMaskSize);
  a.textures.masks_a = masks[0];
  a.textures.masks_b = masks[1];
  return a;
}

FaceDraw face_draw(FaceId face, const codec::FaceParams& params, const glm::mat4& place) {
  HeadPose pose;
  pose.yaw_rad = params.head_yaw_rad;
  pose.pitch_rad = params.head_pitch_rad;
  pose.roll_rad = params.head_roll_rad;
  pose.translation = glm::vec3(params.head_translation_mm[0], params.head_translation_mm[1],
                               params.head_translation_mm[2]) / model::kMillimetresPerUnit;
  FaceDraw draw{face, head_transform(pose, place), {}};
  draw.eye_yaw_pitch_rad[0] = {params.eye_right.yaw_rad, params.eye_right.pitch_rad};
  draw.eye_yaw_pitch_rad[1] = {params.eye_left.yaw_rad, params.eye_left.pitch_rad};
  draw.lid_closure = {params.lid_right, params.lid_left};
  draw.blush = params.blush;
  draw.pallor = params.pallor;
  return draw;
}

}  // namespace fw::render
