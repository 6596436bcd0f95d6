#include "projective_local_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "hot_clones.hpp"
#include "bulk_curve.hpp"
#include "wedge_volume.hpp"

namespace fw::physics::detail {
namespace {

constexpr std::size_t kBlock = 128;


// One spring's weighted pull w (p + A u) from b's side, d = q_b - q_a, ub
// and ua the ends' u: the projection's direction now at the length the
// curve asks, plus the spring's share of L u. One expression for the
// per-face kernel and the one across faces, so a face gets the same bits in
// both.
struct SpringPull {
  float x, y, z;
};
struct SpringEnds {
  float dx, dy, dz, ubx, uby, ubz, uax, uay, uaz;
};
FW_PHYSICS_ALWAYS_INLINE SpringPull spring_pull(const SpringEnds& e, float length, float knee, float weight, float soft,
                                                float compression) {
  const float dx = e.dx, dy = e.dy, dz = e.dz;
  const float length2 = std::max(dx * dx + dy * dy + dz * dz, 1e-18f);
  const float inverse = 1.0f / std::sqrt(length2), now = length2 * inverse;
  // k2 (now - target) = k1 (max(0, d) + c min(0, d)) + (k2 - k1) max(0, now - knee), d = now - L0:
  // a slack unit (c = 0) shorter than its natural length targets its own length.
  const float from_natural = now - length;
  const float linear = std::max(0.0f, from_natural) + compression * std::min(0.0f, from_natural);
  const float stretch = soft * linear + (1.0f - soft) * std::max(0.0f, now - knee);
  const float scale = (now - stretch) * inverse;
  return {weight * (scale * dx + e.ubx - e.uax), weight * (scale * dy + e.uby - e.uay), weight * (scale * dz + e.ubz - e.uaz)};
}

// Springs in blocks: every projection of a block first (no writes to shared
// nodes, so the loop vectorises), then the block added onto its nodes.
FW_HOT_CLONES
void add_spring_projections(const ProjectiveSystem& s, const NodeVectors& q, const NodeVectors& u, NodeSum4* out) {
  const std::uint16_t* sa = s.spring_a.data();
  const std::uint16_t* sb = s.spring_b.data();
  const float* length = s.spring_length.data();
  const float* knee = s.spring_knee_length.data();
  const float* weight = s.spring_weight.data();
  const float* soft = s.spring_soft_share.data();
  const float* compression = s.spring_compression.data();
  const std::size_t count = s.spring_a.size();
  float g[kBlock][4];  // per spring x, y, z and 0, as a node's sum is laid out
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t size = std::min(kBlock, count - begin);
    for (std::size_t j = 0; j < size; ++j) {
      const std::size_t i = begin + j, a = sa[i], b = sb[i];
      const SpringEnds ends{q.x[b] - q.x[a], q.y[b] - q.y[a], q.z[b] - q.z[a], u.x[b], u.y[b], u.z[b], u.x[a], u.y[a], u.z[a]};
      const SpringPull pull = spring_pull(ends, length[i], knee[i], weight[i], soft[i], compression[i]);
      g[j][0] = pull.x, g[j][1] = pull.y, g[j][2] = pull.z, g[j][3] = 0.0f;
    }
    for (std::size_t j = 0; j < size; ++j) {
      NodeSum4 pull;
      std::memcpy(&pull, g[j], sizeof pull);
      out[sa[begin + j]] -= pull;
      out[sb[begin + j]] += pull;
    }
  }
}

// The springs of W faces at once, each face a lane of the interleaved
// arrays: a spring's ends are two runs of 3 W floats, loaded and added to
// as vectors, where one face at a time gathers twelve scattered floats per
// spring (the local step's largest cost). The material is the batch's
// (ProjectiveSystem checks it); each face has its own rest lengths.
template <std::size_t W>
FW_PHYSICS_ALWAYS_INLINE void add_spring_projections_across(const ProjectiveSystem* const* systems, const float* __restrict q,
                                                            const float* __restrict u, float* __restrict out) {
  const ProjectiveSystem& s = *systems[0];
  const std::uint16_t* sa = s.spring_a.data();
  const std::uint16_t* sb = s.spring_b.data();
  const float* weight = s.spring_weight.data();
  const float* soft = s.spring_soft_share.data();
  const float* compression = s.spring_compression.data();
  const float* lengths[W];
  const float* knees[W];
  for (std::size_t k = 0; k < W; ++k) lengths[k] = systems[k]->spring_length.data(), knees[k] = systems[k]->spring_knee_length.data();
  const std::size_t count = s.spring_a.size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t a = sa[i] * 3 * W, b = sb[i] * 3 * W;
    float length[W], knee[W], gx[W], gy[W], gz[W];
    for (std::size_t k = 0; k < W; ++k) length[k] = lengths[k][i], knee[k] = knees[k][i];
    for (std::size_t k = 0; k < W; ++k) {
      const SpringEnds ends{q[b + k] - q[a + k], q[b + W + k] - q[a + W + k], q[b + 2 * W + k] - q[a + 2 * W + k],
                            u[b + k],            u[b + W + k],               u[b + 2 * W + k],
                            u[a + k],            u[a + W + k],               u[a + 2 * W + k]};
      const SpringPull pull = spring_pull(ends, length[k], knee[k], weight[i], soft[i], compression[i]);
      gx[k] = pull.x, gy[k] = pull.y, gz[k] = pull.z;
    }
    for (std::size_t k = 0; k < W; ++k) out[a + k] -= gx[k], out[a + W + k] -= gy[k], out[a + 2 * W + k] -= gz[k];
    for (std::size_t k = 0; k < W; ++k) out[b + k] += gx[k], out[b + W + k] += gy[k], out[b + 2 * W + k] += gz[k];
  }
}


// A prism's constraint is on its six corners about their centroid
// (A = I - 1 1^T / 6, so A^T A = A): the target moves them along the volume
// gradient by lambda = (V0 - V) / |grad V|^2, one Newton step onto the rest
// volume. The gradient sums to zero (moving a prism keeps its volume), so
// the target stays about the centroid. Past the bulk curve's knee lambda
// reaches further by the stiffer slope's extra share. One expression for the per-face
// kernel and the one across faces, as for the springs.
struct PrismCorners {
  float px[6], py[6], pz[6], ux[6], uy[6], uz[6];  ///< positions q and u of corners 0..2 outer, 3..5 inner
};
FW_PHYSICS_ALWAYS_INLINE void prism_pull(const PrismCorners& c, float rest_volume, float w, float knee, float extra,
                                         float (&pull)[6][3]) {
  float gradient[6][3];
  const float volume = wedge_volume_gradient(c.px, c.py, c.pz, gradient);
  float g2 = 0.0f;
#pragma GCC unroll 6
  for (int k = 0; k < 6; ++k)
    g2 += gradient[k][0] * gradient[k][0] + gradient[k][1] * gradient[k][1] + gradient[k][2] * gradient[k][2];
  const float lambda = restoring_volume(rest_volume - volume, rest_volume, knee, extra) / std::max(g2, 1e-30f);
  // The projection about the centroid and the prism's share of L u,
  // both about their centroids: w (q - centroid(q) + lambda grad V +
  // u - centroid(u)).
  float cx = 0.0f, cy = 0.0f, cz = 0.0f;
#pragma GCC unroll 6
  for (int k = 0; k < 6; ++k) cx += c.px[k] + c.ux[k], cy += c.py[k] + c.uy[k], cz += c.pz[k] + c.uz[k];
  cx *= 1.0f / 6.0f, cy *= 1.0f / 6.0f, cz *= 1.0f / 6.0f;
#pragma GCC unroll 6
  for (int k = 0; k < 6; ++k) {
    pull[k][0] = w * (c.px[k] + c.ux[k] - cx + lambda * gradient[k][0]);
    pull[k][1] = w * (c.py[k] + c.uy[k] - cy + lambda * gradient[k][1]);
    pull[k][2] = w * (c.pz[k] + c.uz[k] - cz + lambda * gradient[k][2]);
  }
}

// Prisms in blocks likewise.
FW_HOT_CLONES
void add_volume_projections(const ProjectiveSystem& s, const NodeVectors& q, const NodeVectors& u, NodeSum4* out) {
  const std::size_t count = s.element_weight.size();
  const std::uint16_t* corner[6];
  for (std::size_t k = 0; k < 6; ++k) corner[k] = s.element_node[k].data();
  float g[18][kBlock];
  for (std::size_t begin = 0; begin < count; begin += kBlock) {
    const std::size_t size = std::min(kBlock, count - begin);
    for (std::size_t j = 0; j < size; ++j) {
      const std::size_t e = begin + j;
      PrismCorners c;
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k) {
        const std::size_t node = corner[k][e];
        c.px[k] = q.x[node], c.py[k] = q.y[node], c.pz[k] = q.z[node];
        c.ux[k] = u.x[node], c.uy[k] = u.y[node], c.uz[k] = u.z[node];
      }
      float pull[6][3];
      prism_pull(c, s.element_rest_volume[e], s.element_weight[e], s.volume_knee, s.volume_extra, pull);
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k)
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) g[k * 3 + axis][j] = pull[k][axis];
    }
    for (std::size_t j = 0; j < size; ++j)
      for (std::size_t k = 0; k < 6; ++k) {
        const std::size_t node = corner[k][begin + j];
        out[node] += NodeSum4{g[k * 3 + 0][j], g[k * 3 + 1][j], g[k * 3 + 2][j], 0.0f};
      }
  }
}

// The prisms of W faces at once, as the springs: each face has its own rest
// volumes; the weights are the batch's (ProjectiveSystem keeps the
// reference's).
template <std::size_t W>
FW_PHYSICS_ALWAYS_INLINE void add_volume_projections_across(const ProjectiveSystem* const* systems, const float* __restrict q,
                                                            const float* __restrict u, float* __restrict out) {
  const ProjectiveSystem& s = *systems[0];
  const std::size_t count = s.element_weight.size();
  const std::uint16_t* corner[6];
  for (std::size_t k = 0; k < 6; ++k) corner[k] = s.element_node[k].data();
  const float* rest_volumes[W];
  for (std::size_t lane = 0; lane < W; ++lane) rest_volumes[lane] = systems[lane]->element_rest_volume.data();
  for (std::size_t e = 0; e < count; ++e) {
    std::size_t at[6];  // each corner's run of 3 W values
    for (std::size_t k = 0; k < 6; ++k) at[k] = corner[k][e] * 3 * W;
    float rest[W], g[18][W];
    for (std::size_t lane = 0; lane < W; ++lane) rest[lane] = rest_volumes[lane][e];
    const float w = s.element_weight[e];
    for (std::size_t lane = 0; lane < W; ++lane) {
      PrismCorners c;
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k) {
        const float* qk = q + at[k] + lane;
        const float* uk = u + at[k] + lane;
        c.px[k] = qk[0], c.py[k] = qk[W], c.pz[k] = qk[2 * W];
        c.ux[k] = uk[0], c.uy[k] = uk[W], c.uz[k] = uk[2 * W];
      }
      float pull[6][3];
      prism_pull(c, rest[lane], w, s.volume_knee, s.volume_extra, pull);
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k)
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) g[k * 3 + axis][lane] = pull[k][axis];
    }
    for (std::size_t k = 0; k < 6; ++k)
      for (std::size_t axis = 0; axis < 3; ++axis)
        for (std::size_t lane = 0; lane < W; ++lane) out[at[k] + axis * W + lane] += g[k * 3 + axis][lane];
  }
}

#define FW_ACROSS(W)                                                                                                 \
  FW_HOT_CLONES void add_projections_across_##W(const ProjectiveSystem* const* systems, const float* q, const float* u, \
                                                float* out) {                                                          \
    add_spring_projections_across<W>(systems, q, u, out);                                                            \
    add_volume_projections_across<W>(systems, q, u, out);                                                            \
  }
FW_ACROSS(2)
FW_ACROSS(4)
FW_ACROSS(8)
FW_ACROSS(16)
#undef FW_ACROSS

}  // namespace

void add_projections(const ProjectiveSystem& system, const NodeVectors& q, const NodeVectors& u, NodeSum4* out) {
  add_spring_projections(system, q, u, out);
  add_volume_projections(system, q, u, out);
}

void add_projections_across(std::span<const ProjectiveSystem* const> systems, const float* q, const float* u, float* out) {
  switch (systems.size()) {
    case 2: return add_projections_across_2(systems.data(), q, u, out);
    case 4: return add_projections_across_4(systems.data(), q, u, out);
    case 8: return add_projections_across_8(systems.data(), q, u, out);
    case 16: return add_projections_across_16(systems.data(), q, u, out);
    default: throw std::invalid_argument("projective dynamics: a batch is 2, 4, 8 or 16 faces wide");
  }
}

}  // namespace fw::physics::detail
