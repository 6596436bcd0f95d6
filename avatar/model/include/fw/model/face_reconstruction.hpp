#pragma once
// Expressive-texture reconstruction: the skin of one face for one frame,
// from its FaceParams: neutral + sum of AU weight x (vertex morph, texture
// slide) + sum of corrective weight x corrective component (the physics
// face's residual, vertices only), then the lids closed by their closure.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/avatar_model.hpp"

namespace fw::model {

struct FaceShape {
  std::vector<glm::vec3> positions;  ///< #V skin positions, model units
  std::vector<glm::vec2> uvs;        ///< #V skin texture coordinates
};

/// The skin shaped by `params`' action units and lids (head pose, gaze and
/// colour are the renderer's). AU intensities are clamped to [0,1], lid
/// closures too, corrective weights to [-1,1] (a non-finite one is 0).
FaceShape reconstruct_face(const AvatarModel& avatar, const codec::FaceParams& params);

}  // namespace fw::model
