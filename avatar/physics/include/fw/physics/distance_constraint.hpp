#pragma once
// Position-based dynamics kernel: one distance constraint. Stateless; the
// face simulation owns the arrays it is applied to.
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
bool solve_distance(const glm::vec3& p0, float w0, const glm::vec3& p1, float w1, float rest, float stiffness,
                    glm::vec3& correction0, glm::vec3& correction1);

}  // namespace fw::physics
