#include "fw/render/camera.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace fw::render {

glm::mat4 Camera::view() const { return glm::lookAt(position, target, glm::vec3(0.0f, 1.0f, 0.0f)); }

glm::mat4 Camera::projection() const { return glm::perspective(fov_y_rad, aspect, near_plane, far_plane); }

Camera Camera::portrait(float aspect) {
  Camera camera;
  camera.aspect = aspect;
  // The skin spans about y in [-2.1, 1.6]: 4.4 units of height fit a 30
  // degree view at 8.2 units, leaving a little margin around the head.
  camera.position = {0.0f, -0.25f, 8.2f};
  camera.target = {0.0f, -0.25f, 0.0f};
  if (aspect < 1.0f) camera.position.z /= aspect;  // portrait-format images: keep the width
  return camera;
}

glm::mat4 place_in_row(int index, int count) {
  constexpr float kSpacing = 3.4f;  // a head is about 2.8 units wide with its rim
  const float x = (static_cast<float>(index) - 0.5f * static_cast<float>(count - 1)) * kSpacing;
  return glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f));
}

Camera Camera::group(int count, float aspect) {
  Camera camera = portrait(aspect);
  const float width_needed = 3.4f * static_cast<float>(count);
  const float distance_for_width = width_needed / (2.0f * std::tan(camera.fov_y_rad / 2.0f) * aspect);
  camera.position.z = std::max(camera.position.z, distance_for_width);
  return camera;
}

glm::mat4 head_transform(const HeadPose& pose, const glm::mat4& place) {
  const glm::mat4 m = glm::translate(place, pose.translation + kNeckPivot) *
                      glm::mat4(model::head_rotation(pose.yaw_rad, pose.pitch_rad, pose.roll_rad));
  return glm::translate(m, -kNeckPivot);
}

glm::mat4 eye_transform(glm::vec3 centre, float yaw_rad, float pitch_rad) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), centre);
  m = glm::rotate(m, yaw_rad, glm::vec3(0, 1, 0));
  m = glm::rotate(m, -pitch_rad, glm::vec3(1, 0, 0));
  return glm::translate(m, -centre);
}

glm::vec3 project_to_pixel(const Camera& camera, glm::vec3 p, int width, int height) {
  const glm::vec4 clip = camera.view_projection() * glm::vec4(p, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width), (0.5f - ndc.y * 0.5f) * static_cast<float>(height),
          ndc.z};
}

}  // namespace fw::render
