#pragma once
// Cameras and head poses: where faces are seen from and how a head turns.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/model/head_pose.hpp"

namespace fw::render {

struct Camera {
  glm::vec3 position{0.0f, 0.0f, 8.0f};  ///< model units
  glm::vec3 target{0.0f, -0.25f, 0.0f};
  float fov_y_rad = 0.5236f;              ///< 30 degrees: a portrait lens
  float aspect = 1.0f;                    ///< width / height
  float near_plane = 0.5f, far_plane = 100.0f;

  glm::mat4 view() const;
  glm::mat4 projection() const;
  glm::mat4 view_projection() const { return projection() * view(); }

  /// A camera framing one face from the front, head and rim filling the height.
  static Camera portrait(float aspect);
  /// A camera that sees `count` faces placed by place_in_row().
  static Camera group(int count, float aspect);
};

/// The point heads turn about (model/head_pose.hpp).
inline constexpr glm::vec3 kNeckPivot = model::kNeckPivot;

/// A head's rotation (radians) and translation (model units). Signs follow
/// codec::FaceParams: yaw turns toward the person's left (the nose moves to
/// the viewer's right), pitch up, roll toward the person's left shoulder.
struct HeadPose {
  float yaw_rad = 0, pitch_rad = 0, roll_rad = 0;
  glm::vec3 translation{0.0f};
};

/// Model matrix of a head at `pose`, standing at `place` (where a room puts it).
glm::mat4 head_transform(const HeadPose& pose, const glm::mat4& place = glm::mat4(1.0f));

/// Rotation of an eyeball about its centre; same signs as the head.
glm::mat4 eye_transform(glm::vec3 centre, float yaw_rad, float pitch_rad);

/// Where the i-th of `count` faces stands when they are shown side by side.
glm::mat4 place_in_row(int index, int count);

/// Pixel position (x right, y down, origin top left) of world point `p` in an
/// image of width x height seen by `camera`; z is the NDC depth in [-1,1].
glm::vec3 project_to_pixel(const Camera& camera, glm::vec3 p, int width, int height);

}  // namespace fw::render
