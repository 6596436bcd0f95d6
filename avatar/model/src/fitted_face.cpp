#include "fw/model/fitted_face.hpp"

#include <cassert>

#include "fw/model/head_shell.hpp"

namespace fw::model {
namespace {

// Mean displacement of some skin vertices from the generic to the fitted face.
glm::vec2 mean_shift(const GenericFace& generic, std::span<const glm::vec2> fitted_xy, int begin, int end) {
  glm::vec2 sum(0.0f);
  for (int i = begin; i < end; ++i) {
    const std::uint32_t v = generic.landmark_vertices[static_cast<std::size_t>(i)];
    sum += fitted_xy[v] - glm::vec2(generic.skin.positions[v]);
  }
  return sum / static_cast<float>(end - begin);
}

void shift_mesh(Mesh& mesh, glm::vec2 shift) {
  for (glm::vec3& p : mesh.positions) p += glm::vec3(shift, 0.0f);
}

}  // namespace

GenericFace fit_generic_face(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                             std::span<const float> head_outline) {
  assert(fitted_xy.size() == generic.skin.positions.size());
  GenericFace face = generic;
  for (std::size_t v = 0; v < fitted_xy.size(); ++v) {
    face.skin.positions[v].x = fitted_xy[v].x;
    face.skin.positions[v].y = fitted_xy[v].y;
    face.skin.uvs[v] = face.texture_frame.to_uv(fitted_xy[v]);
  }
  // Eyeballs follow the eye centres (which alignment keeps near (+-0.5, 0));
  // the mouth cavity follows the lips.
  const int eye_begin[2] = {landmarks::kEyeRightBegin, landmarks::kEyeLeftBegin};
  for (std::size_t side = 0; side < 2; ++side) {
    const glm::vec2 shift = mean_shift(generic, fitted_xy, eye_begin[side], eye_begin[side] + 6);
    face.eyes[side].centre += glm::vec3(shift, 0.0f);
    shift_mesh(face.eyes[side].mesh, shift);
  }
  shift_mesh(face.mouth_cavity, mean_shift(generic, fitted_xy, landmarks::kOuterLipBegin, landmarks::kOuterLipEnd));
  face.head = fit_head_shell(generic, fitted_xy, head_outline);
  return face;
}

}  // namespace fw::model
