#pragma once
// Turning an avatar package into what the renderer draws: the fitted face
// and its textures.
#include <string>

#include "fw/model/avatar_package.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::render {

struct AvatarAppearance {
  model::GenericFace face;  ///< the generic face fitted to the person
  FaceTextures textures;
};

/// Decodes the package's images and fits the generic face.
/// @return false and `error` if an image is damaged or out of bounds
bool load_avatar_appearance(const model::AvatarPackage& package, AvatarAppearance& appearance, std::string& error);

}  // namespace fw::render
