#pragma once
// Turning an avatar package into what the renderer draws: the fitted face
// and its textures.
#include <string>

#include "fw/codec/face_params.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/procedural_texture.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::render {

struct AvatarAppearance {
  model::AvatarModel avatar;  ///< the generic face fitted to the person, with its morphs
  FaceTextures textures;
};

/// Decodes the package's images and fits the generic face.
/// @return false and `error` if an image is damaged or out of bounds
bool load_avatar_appearance(const model::AvatarPackage& package, AvatarAppearance& appearance, std::string& error);

/// The generic face with procedural textures in the colours of `look`.
AvatarAppearance generic_appearance(const model::Appearance& look);

/// How a face with `params` is drawn standing at `place`: head pose (the
/// translation's millimetres in model units), gaze, lids, blood colour. The
/// skin's shape comes separately (model::reconstruct_face).
FaceDraw face_draw(FaceId face, const codec::FaceParams& params, const glm::mat4& place = glm::mat4(1.0f));

}  // namespace fw::render
