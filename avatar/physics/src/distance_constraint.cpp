#include "fw/physics/distance_constraint.hpp"

#include <glm/geometric.hpp>

namespace fw::physics {

bool solve_distance(const glm::vec3& p0, float w0, const glm::vec3& p1, float w1, float rest, float stiffness,
                    glm::vec3& correction0, glm::vec3& correction1) {
  correction0 = correction1 = glm::vec3(0.0f);
  const float w = w0 + w1;
  const glm::vec3 d = p0 - p1;
  const float length = glm::length(d);
  if (w <= 0.0f || length < 1e-9f) return false;
  const glm::vec3 n = d / length;
  const float c = length - rest;
  correction0 = -stiffness * w0 / w * c * n;
  correction1 = +stiffness * w1 / w * c * n;
  return true;
}

}  // namespace fw::physics
