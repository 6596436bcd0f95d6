#include "fw/render/avatar_appearance.hpp"

#include "fw/model/fitted_face.hpp"
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
  if (!decode(package.face_texture, "face_texture", loaded.textures.skin)) return false;
  if (!decode(package.eye, "eye", loaded.textures.eye)) return false;
  if (!decode(package.mouth, "mouth", loaded.textures.mouth)) return false;
  loaded.face = model::fit_generic_face(model::generic_face(), package.fitted_vertices);
  appearance = std::move(loaded);
  return true;
}

}  // namespace fw::render
