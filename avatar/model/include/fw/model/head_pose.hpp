#pragma once
// A head's pose and how it turns, shared by what draws a head
// (avatar/render), what places its gaze in a room (avatar/behavior) and what
// simulates its tissue in the head's frame (avatar/physics, whose loads from
// a turning head grow with the distance from the pivot). The browser's
// engine has its own copy (web/engine/head_pose.js).
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"

namespace fw::model {

/// The point a head turns about: the top of the neck, below the ears, level
/// with them in depth (the face surface reaches about z = 2.2 at the nose),
/// model units.
inline constexpr glm::vec3 kNeckPivot{0.0f, -1.5f, 0.2f};

/// A head's pose, codec::FaceParams' signs: yaw toward the person's left
/// (the nose moves to the viewer's right), pitch up, roll toward the
/// person's left shoulder, radians; translation from rest in mm.
struct HeadPose {
  float yaw_rad = 0, pitch_rad = 0, roll_rad = 0;
  glm::vec3 translation_mm{0.0f};
  bool operator==(const HeadPose&) const = default;
};

/// The head pose a frame's parameters give.
inline HeadPose head_pose(const codec::FaceParams& p) {
  return {p.head_yaw_rad, p.head_pitch_rad, p.head_roll_rad,
          {p.head_translation_mm[0], p.head_translation_mm[1], p.head_translation_mm[2]}};
}

/// The head's rotation, head frame to world: roll, then pitch, then yaw,
/// about the neck pivot.
inline glm::mat3 head_rotation(float yaw_rad, float pitch_rad, float roll_rad) {
  glm::mat4 m = glm::rotate(glm::mat4(1.0f), yaw_rad, glm::vec3(0, 1, 0));
  m = glm::rotate(m, -pitch_rad, glm::vec3(1, 0, 0));
  m = glm::rotate(m, -roll_rad, glm::vec3(0, 0, 1));
  return glm::mat3(m);
}
inline glm::mat3 head_rotation(const HeadPose& pose) { return head_rotation(pose.yaw_rad, pose.pitch_rad, pose.roll_rad); }

}  // namespace fw::model
