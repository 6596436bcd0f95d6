#pragma once
// The wedge volume of a prism and its gradient (prism_volume.hpp) written
// out on scalars, so that a loop over a block of elements vectorises: the
// mass-spring solver's volume forces and the projective solver's volume
// projections share it.
#include "fw/physics/prism_volume.hpp"

namespace fw::physics::detail {

/// Edges of the outer (a), inner (b) and middle (m) triangles from their corner 0.
struct WedgeEdges {
  float a1x, a1y, a1z, a2x, a2y, a2z;
  float b1x, b1y, b1z, b2x, b2y, b2z;
  float m1x, m1y, m1z, m2x, m2y, m2z;
};

/// The wedge's volume as S . d / 12: S = N_a + 4 N_m + N_b, the weighted
/// normals of its outer, middle and inner triangles, and d the mean of
/// (outer - inner) corners, its depth.
/// @param[in]  px, py, pz  the six nodes (0..2 outer, 3..5 inner)
/// @param[out] normal      S
/// @param[out] depth       d
/// @return the triangles' edges
FW_PHYSICS_ALWAYS_INLINE WedgeEdges wedge_normal_and_depth(const float* px, const float* py, const float* pz,
                                                           float (&normal)[3], float (&depth)[3]) {
  constexpr float kThird = 1.0f / 3.0f;
  WedgeEdges e;
  e.a1x = px[1] - px[0], e.a1y = py[1] - py[0], e.a1z = pz[1] - pz[0];
  e.a2x = px[2] - px[0], e.a2y = py[2] - py[0], e.a2z = pz[2] - pz[0];
  e.b1x = px[4] - px[3], e.b1y = py[4] - py[3], e.b1z = pz[4] - pz[3];
  e.b2x = px[5] - px[3], e.b2y = py[5] - py[3], e.b2z = pz[5] - pz[3];
  e.m1x = 0.5f * (e.a1x + e.b1x), e.m1y = 0.5f * (e.a1y + e.b1y), e.m1z = 0.5f * (e.a1z + e.b1z);
  e.m2x = 0.5f * (e.a2x + e.b2x), e.m2y = 0.5f * (e.a2y + e.b2y), e.m2z = 0.5f * (e.a2z + e.b2z);
  normal[0] = (e.a1y * e.a2z - e.a1z * e.a2y) + (e.b1y * e.b2z - e.b1z * e.b2y) + 4.0f * (e.m1y * e.m2z - e.m1z * e.m2y);
  normal[1] = (e.a1z * e.a2x - e.a1x * e.a2z) + (e.b1z * e.b2x - e.b1x * e.b2z) + 4.0f * (e.m1z * e.m2x - e.m1x * e.m2z);
  normal[2] = (e.a1x * e.a2y - e.a1y * e.a2x) + (e.b1x * e.b2y - e.b1y * e.b2x) + 4.0f * (e.m1x * e.m2y - e.m1y * e.m2x);
  depth[0] = kThird * (px[0] + px[1] + px[2] - px[3] - px[4] - px[5]);
  depth[1] = kThird * (py[0] + py[1] + py[2] - py[3] - py[4] - py[5]);
  depth[2] = kThird * (pz[0] + pz[1] + pz[2] - pz[3] - pz[4] - pz[5]);
  return e;
}

/// @param[in]  px, py, pz  the six nodes (0..2 outer, 3..5 inner)
/// @param[out] gradient    dV/dp per node and axis
/// @return the signed volume
FW_PHYSICS_ALWAYS_INLINE float wedge_volume_gradient(const float* px, const float* py, const float* pz, float (&gradient)[6][3]) {
  constexpr float kTwelfth = 1.0f / 12.0f, kSixth = 1.0f / 6.0f;
  float normal[3], depth[3];
  const WedgeEdges e = wedge_normal_and_depth(px, py, pz, normal, depth);
  const float sx = normal[0], sy = normal[1], sz = normal[2], dx = depth[0], dy = depth[1], dz = depth[2];
  const float volume = kTwelfth * (sx * dx + sy * dy + sz * dz);
  // dV/dp: S/36 along the depth (+ outer, - inner), plus for each
  // triangle x in {a, b, m}: d(N_x . d)/dx_i = (x2 - x0) x d at corner 1,
  // d x (x1 - x0) at corner 2, minus both at corner 0; m counts 4/2 on
  // both outer and inner corners.
  auto add_triangle = [&](float e1x, float e1y, float e1z, float e2x, float e2y, float e2z, float w, float* c0, float* c1,
                    float* c2) {
    const float u1x = (e2y * dz - e2z * dy) * w, u1y = (e2z * dx - e2x * dz) * w, u1z = (e2x * dy - e2y * dx) * w;
    const float u2x = (dy * e1z - dz * e1y) * w, u2y = (dz * e1x - dx * e1z) * w, u2z = (dx * e1y - dy * e1x) * w;
    c1[0] += u1x, c1[1] += u1y, c1[2] += u1z;
    c2[0] += u2x, c2[1] += u2y, c2[2] += u2z;
    c0[0] -= u1x + u2x, c0[1] -= u1y + u2y, c0[2] -= u1z + u2z;
  };
  float ga[3][3], gb[3][3], gm[3][3];
  const float depth_x = sx / 36.0f, depth_y = sy / 36.0f, depth_z = sz / 36.0f;
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    ga[k][0] = depth_x, ga[k][1] = depth_y, ga[k][2] = depth_z;
    gb[k][0] = -depth_x, gb[k][1] = -depth_y, gb[k][2] = -depth_z;
    gm[k][0] = gm[k][1] = gm[k][2] = 0.0f;
  }
  add_triangle(e.a1x, e.a1y, e.a1z, e.a2x, e.a2y, e.a2z, kTwelfth, ga[0], ga[1], ga[2]);
  add_triangle(e.b1x, e.b1y, e.b1z, e.b2x, e.b2y, e.b2z, kTwelfth, gb[0], gb[1], gb[2]);
  add_triangle(e.m1x, e.m1y, e.m1z, e.m2x, e.m2y, e.m2z, kSixth, gm[0], gm[1], gm[2]);
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k)
#pragma GCC unroll 3
    for (int c = 0; c < 3; ++c) {
      gradient[k][c] = ga[k][c] + gm[k][c];
      gradient[3 + k][c] = gb[k][c] + gm[k][c];
    }
  return volume;
}

}  // namespace fw::physics::detail
