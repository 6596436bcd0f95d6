#include "head_points.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/render/avatar_appearance.hpp"

namespace fw::client {

const HeadPoints& head_points() {
  static const HeadPoints points = [] {
    const model::GenericFace& face = model::generic_face();
    HeadPoints p{};
    p.eye_mid = 0.5f * (face.eyes[0].centre + face.eyes[1].centre);
    p.interocular = glm::length(face.eyes[0].centre - face.eyes[1].centre);
    p.chin = face.skin.positions[face.landmark_vertices[model::landmarks::kChin]];
    p.top = glm::vec3(0.0f, -1e9f, 0.0f);
    for (const glm::vec3& v : face.head.mesh.positions) {
      if (v.y > p.top.y) p.top = v;
      p.half_width = std::max(p.half_width, std::abs(v.x));
    }
    return p;
  }();
  return points;
}

glm::vec3 eyes_at(const glm::mat4& place, const codec::FaceParams& params) {
  const glm::mat4 model = render::face_draw(0, params, place).model;
  return glm::vec3(model * glm::vec4(head_points().eye_mid, 1.0f));
}

glm::mat4 seat_place(float x_mm, float y_mm, float z_mm, float facing_yaw_rad) {
  const glm::vec3 origin = glm::vec3(x_mm, y_mm, z_mm) / model::kMillimetresPerUnit;
  return glm::rotate(glm::translate(glm::mat4(1.0f), origin), facing_yaw_rad, glm::vec3(0.0f, 1.0f, 0.0f));
}

YawPitch angles_at(const glm::mat4& place, glm::vec3 d) {
  // Into the place's frame (rotation only: places carry no scale but the
  // self-view's, whose own gaze is never aimed).
  const glm::vec3 local = glm::transpose(glm::mat3(place)) * d;
  const float horizontal = std::sqrt(local.x * local.x + local.z * local.z);
  return {std::atan2(local.x, local.z), std::atan2(local.y, horizontal)};
}

}  // namespace fw::client
