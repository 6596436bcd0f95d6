#include "tissue_forces.hpp"

#include <algorithm>
#include <cmath>

namespace fw::physics::detail {
namespace {

constexpr std::size_t kBlock = 128;

// Built twice, for AVX2/FMA machines and for any x86-64, and chosen at load
// time: the block loops then vectorise with gathers where the CPU has them.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define FW_HOT_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define FW_HOT_CLONES
#endif

}  // namespace

SpringKindTable spring_kind_table(const TissueMaterial& material) {
  SpringKindTable t{};
  for (std::size_t k = 0; k < kSpringKindCount; ++k) {
    const StressStrainCurve& c = material.curves[k];
    t.k1[k] = c.stiffness;
    t.k2_extra[k] = c.stiffness * (c.stiff_ratio - 1.0f);
    t.slack[k] = 1.0f - c.residual_strain;
    t.knee[k] = 1.0f - c.residual_strain + c.knee_strain;
    t.damping[k] = material.damping[k];
  }
  return t;
}

FW_HOT_CLONES
void add_spring_forces(const TissueModel& model, const SpringKindTable& table, const NodeArrays& n) {
  const std::uint16_t* sa = model.spring_a.data();
  const std::uint16_t* sb = model.spring_b.data();
  const float* rest = model.spring_rest.data();
  const SpringKind* kinds = model.spring_kind.data();
  const std::size_t count = model.spring_count();
  float gx[kBlock], gy[kBlock], gz[kBlock];
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t size = std::min(kBlock, count - begin);
    for (std::size_t j = 0; j < size; ++j) {
      const std::size_t s = begin + j;
      const std::size_t a = sa[s], b = sb[s];
      const auto kind = static_cast<std::size_t>(kinds[s]);
      const float dx = n.x[b] - n.x[a], dy = n.y[b] - n.y[a], dz = n.z[b] - n.z[a];
      // Branch-free (coincident ends give dx = dy = dz = 0, hence no force).
      const float length2 = std::max(dx * dx + dy * dy + dz * dz, 1e-18f);
      const float inv = 1.0f / std::sqrt(length2);
      const float length = length2 * inv;
      const float speed = ((n.vx[b] - n.vx[a]) * dx + (n.vy[b] - n.vy[a]) * dy + (n.vz[b] - n.vz[a]) * dz) * inv;
      const float force = table.k1[kind] * (length - rest[s] * table.slack[kind]) +
                          table.k2_extra[kind] * std::max(0.0f, length - rest[s] * table.knee[kind]) +
                          table.damping[kind] * speed;
      const float scale = force * inv;
      gx[j] = scale * dx;
      gy[j] = scale * dy;
      gz[j] = scale * dz;
    }
    for (std::size_t j = 0; j < size; ++j) {
      const std::size_t a = sa[begin + j], b = sb[begin + j];
      n.fx[a] += gx[j], n.fy[a] += gy[j], n.fz[a] += gz[j];
      n.fx[b] -= gx[j], n.fy[b] -= gy[j], n.fz[b] -= gz[j];
    }
  }
}

// The wedge volume and its gradient (prism_volume.hpp), written out on
// scalars so that a block of elements vectorises.
FW_HOT_CLONES
void add_volume_forces(const TissueModel& model, const NodeArrays& n) {
  const float stiffness = model.material.volume_stiffness;
  const std::size_t count = model.element_count();
  const std::uint16_t* corner[6];
  for (std::size_t k = 0; k < 6; ++k) corner[k] = model.element_node[k].data();
  constexpr float kTwelfth = 1.0f / 12.0f, kSixth = 1.0f / 6.0f, kThird = 1.0f / 3.0f;
  float g[18][kBlock];
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t size = std::min(kBlock, count - begin);
    for (std::size_t j = 0; j < size; ++j) {
      const std::size_t e = begin + j;
      float px[6], py[6], pz[6];
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k) {
        const std::size_t node = corner[k][e];
        px[k] = n.x[node], py[k] = n.y[node], pz[k] = n.z[node];
      }
      // Edges of the outer (a), inner (b) and middle (m) triangles from their corner 0.
      const float a1x = px[1] - px[0], a1y = py[1] - py[0], a1z = pz[1] - pz[0];
      const float a2x = px[2] - px[0], a2y = py[2] - py[0], a2z = pz[2] - pz[0];
      const float b1x = px[4] - px[3], b1y = py[4] - py[3], b1z = pz[4] - pz[3];
      const float b2x = px[5] - px[3], b2y = py[5] - py[3], b2z = pz[5] - pz[3];
      const float m1x = 0.5f * (a1x + b1x), m1y = 0.5f * (a1y + b1y), m1z = 0.5f * (a1z + b1z);
      const float m2x = 0.5f * (a2x + b2x), m2y = 0.5f * (a2y + b2y), m2z = 0.5f * (a2z + b2z);
      const float sx = (a1y * a2z - a1z * a2y) + (b1y * b2z - b1z * b2y) + 4.0f * (m1y * m2z - m1z * m2y);
      const float sy = (a1z * a2x - a1x * a2z) + (b1z * b2x - b1x * b2z) + 4.0f * (m1z * m2x - m1x * m2z);
      const float sz = (a1x * a2y - a1y * a2x) + (b1x * b2y - b1y * b2x) + 4.0f * (m1x * m2y - m1y * m2x);
      const float dx = kThird * (px[0] + px[1] + px[2] - px[3] - px[4] - px[5]);
      const float dy = kThird * (py[0] + py[1] + py[2] - py[3] - py[4] - py[5]);
      const float dz = kThird * (pz[0] + pz[1] + pz[2] - pz[3] - pz[4] - pz[5]);
      const float volume = kTwelfth * (sx * dx + sy * dy + sz * dz);
      const float f = stiffness * (model.element_rest_volume[e] - volume) * model.element_force_scale[e];
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
      add_triangle(a1x, a1y, a1z, a2x, a2y, a2z, kTwelfth, ga[0], ga[1], ga[2]);
      add_triangle(b1x, b1y, b1z, b2x, b2y, b2z, kTwelfth, gb[0], gb[1], gb[2]);
      add_triangle(m1x, m1y, m1z, m2x, m2y, m2z, kSixth, gm[0], gm[1], gm[2]);
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k)
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) {
          g[k * 3 + c][j] = f * (ga[k][c] + gm[k][c]);
          g[9 + k * 3 + c][j] = f * (gb[k][c] + gm[k][c]);
        }
    }
    for (std::size_t j = 0; j < size; ++j)
      for (std::size_t k = 0; k < 6; ++k) {
        const std::size_t node = corner[k][begin + j];
        n.fx[node] += g[k * 3 + 0][j];
        n.fy[node] += g[k * 3 + 1][j];
        n.fz[node] += g[k * 3 + 2][j];
      }
  }
}

}  // namespace fw::physics::detail
