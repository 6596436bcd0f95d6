#pragma once
// The points of a head the client aims faces with, taken from the generic
// face it already has (fw/model) and the neck pivot the renderer turns heads
// about (fw/render): the same head geometry the server's behaviour aims
// with, so that the client can work out where the server aimed each face.
// Model units (kMillimetresPerUnit millimetres), the head's model frame: x
// toward the person's left, y up, z out of the face.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"

namespace fw::client {

struct HeadPoints {
  glm::vec3 eye_mid;  ///< between the eyes' rotation centres
  glm::vec3 chin;     ///< the chin landmark on the skin
  glm::vec3 top;      ///< the top of the head (the head shell's highest point)
  float half_width;   ///< of the head shell, seen from the front
  float interocular;  ///< between the eyes' rotation centres
};
const HeadPoints& head_points();

/// Where the eyes (their midpoint) of a face standing at `place` are when its
/// head is posed as in `params` (render::face_draw's head transform).
glm::vec3 eyes_at(const glm::mat4& place, const codec::FaceParams& params);

/// The place (model matrix before the head's own pose) of a seat on the
/// wire: translate(origin) * rotate_y(facing), the server's seat frame.
glm::mat4 seat_place(float x_mm, float y_mm, float z_mm, float facing_yaw_rad);

/// Yaw and pitch (FaceParams' signs) of world direction `d` seen from a face
/// standing at `place`: 0,0 straight out of the face at rest.
struct YawPitch {
  float yaw_rad = 0, pitch_rad = 0;
};
YawPitch angles_at(const glm::mat4& place, glm::vec3 d);

}  // namespace fw::client
