#include "fw/render/avatar_appearance.hpp"

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
  loaded.avatar = model::make_avatar_model(model::generic_face(), package.fitted_vertices);
  appearance = std::move(loaded);
  return true;
}

AvatarAppearance generic_appearance(const model::Appearance& look) {
  constexpr int kMaskSize = 64;
  AvatarAppearance a;
  a.avatar = model::generic_avatar_model();
  const model::GenericFace& face = a.avatar.face;
  a.textures.skin = model::make_skin_texture(face, look);
  a.textures.eye = model::make_eye_texture(face.eyes[0], look);
  a.textures.mouth = model::make_mouth_texture();
  a.textures.closed_lid = model::make_skin_texture(face, look, 512, /*eye_holes=*/false);
  a.textures.closed_lid_rect = {0.0f, 0.0f, 1.0f, 1.0f};
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
