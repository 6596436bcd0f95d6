#include "fw/physics/head_loads.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace fw::physics {
namespace {

// The cross-product matrix: skew(w) v = w x v.
glm::mat3 skew(const glm::vec3& w) {
  // glm is column-major: each glm::vec3 here is a column.
  return glm::mat3(glm::vec3(0.0f, w.z, -w.y), glm::vec3(-w.z, 0.0f, w.x), glm::vec3(w.y, -w.x, 0.0f));
}

bool finite(const HeadPose& p) {
  return std::isfinite(p.yaw_rad) && std::isfinite(p.pitch_rad) && std::isfinite(p.roll_rad) &&
         std::isfinite(p.translation_mm.x) && std::isfinite(p.translation_mm.y) && std::isfinite(p.translation_mm.z);
}

}  // namespace

HeadLoad HeadMotion::advance(double dt_s, float scale) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0 || !finite(next_)) return load_;
  const auto dt = static_cast<float>(dt_s);
  const glm::mat3 rotation = model::head_rotation(next_);
  // The turn over the frame in the head's frame, R_before^T R_now = I +
  // skew(omega dt) for the small turns of one frame.
  const glm::mat3 turn = glm::transpose(rotation_) * rotation;
  glm::vec3 omega = 0.5f / dt * glm::vec3(turn[1][2] - turn[2][1], turn[2][0] - turn[0][2], turn[0][1] - turn[1][0]);
  glm::vec3 pivot_speed = (next_.translation_mm - pivot_mm_) / dt;
  const bool cut = !started_ || glm::length(omega) > kMaxHeadSpeedRadS || glm::length(pivot_speed) > kMaxPivotSpeedMmS;
  if (cut) omega = glm::vec3(0.0f), pivot_speed = glm::vec3(0.0f);
  const glm::vec3 alpha = cut ? glm::vec3(0.0f) : (omega - omega_) / dt;
  const glm::vec3 pivot_acceleration =
      cut ? glm::vec3(0.0f) : (pivot_speed - pivot_speed_mm_s_) / dt / model::kMillimetresPerUnit;
  started_ = true;
  rotation_ = rotation, omega_ = omega, pivot_mm_ = next_.translation_mm, pivot_speed_mm_s_ = pivot_speed;

  const glm::vec3 gravity(0.0f, -kGravityUnits, 0.0f);
  const glm::mat3 to_head = glm::transpose(rotation);
  HeadLoad load;
  load.uniform = scale * (to_head * gravity - gravity - to_head * pivot_acceleration);
  // -(alpha x r) - omega x (omega x r) = -(skew(alpha) + skew(omega)^2) r
  const glm::mat3 w = skew(omega);
  load.linear = -scale * (skew(alpha) + w * w);
  load_ = load;
  return load_;
}

}  // namespace fw::physics
