#pragma once
// Position-based dynamics kernel: one distance constraint. Stateless; the
// face simulation owns the arrays it is applied to. Inline because the PBD
// solver calls it once per spring per sub-step.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace fw::physics {

/// Corrections that restore the distance between two particles
/// (Müller et al., "Position Based Dynamics", 2007, eq. 10-11):
///   C(p0,p1) = |p0 - p1| - rest
///   dp0 = -w0 / (w0 + w1) * C * n,  dp1 = +w1 / (w0 + w1) * C * n,  n = (p0 - p1) / |p0 - p1|
/// scaled by `stiffness`.
/// @param[in]  p0, p1      particle positions
/// @param[in]  w0, w1      inverse masses (0 = fixed)
/// @param[in]  rest        rest distance, >= 0
/// @param[in]  stiffness   in [0,1]
/// @param[out] correction0, correction1  position corrections to add
/// @return false (and zero corrections) if both particles are fixed or coincide
inline bool solve_distance(const glm::vec3& p0, float w0, const glm::vec3& p1, float w1, float rest, float stiffness,
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
