#pragma once
// Kernel: the volume of a triangular prism element and its gradient with
// respect to its six nodes. Lee, Terzopoulos & Waters 1995 (sec. 4.3) keep
// each prism's volume with a force along the volume gradient; the PBD face
// keeps it with a volume constraint (Müller et al. 2007, sec. 4.4).
//
// The prism is the linear wedge between its outer triangle a and inner
// triangle b (its side faces are bilinear), whose volume is exact and does
// not depend on how the nodes are numbered (a split into tetrahedra would,
// and would make the two sides of a symmetric face differ):
//   V = (N_b + 4 N_m + N_a) . d / 12,   N_x = (x1 - x0) x (x2 - x0),
//   m = (a + b) / 2,   d = mean of (a_i - b_i)
// (Simpson's rule in the depth direction is exact: the integrand is quadratic).
#include <array>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace fw::physics {

// Called once per element per PBD sub-step: worth inlining even where the
// compiler's size heuristics would not.
#if defined(__GNUC__)
#define FW_PHYSICS_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define FW_PHYSICS_ALWAYS_INLINE inline
#endif

/// Nodes 0,1,2 are the outer triangle, 3,4,5 the inner one below 0,1,2.
using PrismNodes = std::array<glm::vec3, 6>;

namespace detail {
// d(N_x . w)/dx_i for N_x = (x1 - x0) x (x2 - x0), with w held fixed.
FW_PHYSICS_ALWAYS_INLINE void add_normal_gradient(const glm::vec3& x0, const glm::vec3& x1, const glm::vec3& x2, const glm::vec3& w,
                                float scale, glm::vec3& g0, glm::vec3& g1, glm::vec3& g2) {
  const glm::vec3 d1 = glm::cross(x2 - x0, w) * scale, d2 = glm::cross(w, x1 - x0) * scale;
  g1 += d1;
  g2 += d2;
  g0 -= d1 + d2;
}
}  // namespace detail

/// Signed volume of the prism (positive when the outer triangle is wound
/// counter-clockwise seen from outside and lies outside the inner one).
/// @param[in]  p         the six nodes
/// @param[out] gradient  if not null, dV/dp_i for each node (overwritten)
/// @return the volume, cubic model units
FW_PHYSICS_ALWAYS_INLINE float prism_volume(const PrismNodes& p, PrismNodes* gradient = nullptr) {
  const glm::vec3 &a0 = p[0], &a1 = p[1], &a2 = p[2], &b0 = p[3], &b1 = p[4], &b2 = p[5];
  const glm::vec3 m0 = 0.5f * (a0 + b0), m1 = 0.5f * (a1 + b1), m2 = 0.5f * (a2 + b2);
  const glm::vec3 na = glm::cross(a1 - a0, a2 - a0), nb = glm::cross(b1 - b0, b2 - b0), nm = glm::cross(m1 - m0, m2 - m0);
  const glm::vec3 s = nb + 4.0f * nm + na;
  const glm::vec3 d = ((a0 - b0) + (a1 - b1) + (a2 - b2)) / 3.0f;
  if (gradient) {
    PrismNodes& g = *gradient;
    const glm::vec3 via_depth = s / 36.0f;  // d V / d d = S / 12, and d d / d a_i = 1/3
    for (int k = 0; k < 3; ++k) {
      g[static_cast<std::size_t>(k)] = via_depth;
      g[static_cast<std::size_t>(k + 3)] = -via_depth;
    }
    constexpr float kTwelfth = 1.0f / 12.0f;
    detail::add_normal_gradient(a0, a1, a2, d, kTwelfth, g[0], g[1], g[2]);
    detail::add_normal_gradient(b0, b1, b2, d, kTwelfth, g[3], g[4], g[5]);
    // N_m depends on a_i and b_i through m_i = (a_i + b_i) / 2: 4 / 12 / 2 each.
    glm::vec3 gm0(0.0f), gm1(0.0f), gm2(0.0f);
    detail::add_normal_gradient(m0, m1, m2, d, 4.0f * kTwelfth * 0.5f, gm0, gm1, gm2);
    g[0] += gm0, g[3] += gm0;
    g[1] += gm1, g[4] += gm1;
    g[2] += gm2, g[5] += gm2;
  }
  return glm::dot(s, d) / 12.0f;
}

}  // namespace fw::physics
