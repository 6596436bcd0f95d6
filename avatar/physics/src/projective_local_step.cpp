#include "projective_local_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "hot_clones.hpp"
#include "wedge_volume.hpp"

namespace fw::physics::detail {
namespace {

constexpr std::size_t kBlock = 128;


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
      const float dx = q.x[b] - q.x[a], dy = q.y[b] - q.y[a], dz = q.z[b] - q.z[a];
      const float length2 = std::max(dx * dx + dy * dy + dz * dz, 1e-18f);
      const float inverse = 1.0f / std::sqrt(length2), now = length2 * inverse;
      // k2 (now - target) = k1 (max(0, d) + c min(0, d)) + (k2 - k1) max(0, now - knee), d = now - L0:
      // a slack unit (c = 0) shorter than its natural length targets its own length.
      const float from_natural = now - length[i];
      const float linear = std::max(0.0f, from_natural) + compression[i] * std::min(0.0f, from_natural);
      const float stretch = soft[i] * linear + (1.0f - soft[i]) * std::max(0.0f, now - knee[i]);
      const float scale = (now - stretch) * inverse;
      // w (p + A u): the projection and the spring's share of L u.
      g[j][0] = weight[i] * (scale * dx + u.x[b] - u.x[a]);
      g[j][1] = weight[i] * (scale * dy + u.y[b] - u.y[a]);
      g[j][2] = weight[i] * (scale * dz + u.z[b] - u.z[a]);
      g[j][3] = 0.0f;
    }
    for (std::size_t j = 0; j < size; ++j) {
      NodeSum4 pull;
      std::memcpy(&pull, g[j], sizeof pull);
      out[sa[begin + j]] -= pull;
      out[sb[begin + j]] += pull;
    }
  }
}

// Prisms in blocks likewise. A prism's constraint is on its six corners
// about their centroid (A = I - 1 1^T / 6, so A^T A = A): the target moves
// them along the volume gradient by lambda = (V0 - V) / |grad V|^2, one
// Newton step onto the rest volume. The gradient sums to zero (moving a
// prism keeps its volume), so the target stays about the centroid.
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
      float px[6], py[6], pz[6], ux[6], uy[6], uz[6];
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k) {
        const std::size_t node = corner[k][e];
        px[k] = q.x[node], py[k] = q.y[node], pz[k] = q.z[node];
        ux[k] = u.x[node], uy[k] = u.y[node], uz[k] = u.z[node];
      }
      float gradient[6][3];
      const float volume = wedge_volume_gradient(px, py, pz, gradient);
      float g2 = 0.0f;
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k)
        g2 += gradient[k][0] * gradient[k][0] + gradient[k][1] * gradient[k][1] + gradient[k][2] * gradient[k][2];
      const float w = s.element_weight[e];
      const float lambda = (s.element_rest_volume[e] - volume) / std::max(g2, 1e-30f);
      // The projection about the centroid and the prism's share of L u,
      // both about their centroids: w (q - centroid(q) + lambda grad V +
      // u - centroid(u)).
      float cx = 0.0f, cy = 0.0f, cz = 0.0f;
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k) cx += px[k] + ux[k], cy += py[k] + uy[k], cz += pz[k] + uz[k];
      cx *= 1.0f / 6.0f, cy *= 1.0f / 6.0f, cz *= 1.0f / 6.0f;
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k) {
        g[k * 3 + 0][j] = w * (px[k] + ux[k] - cx + lambda * gradient[k][0]);
        g[k * 3 + 1][j] = w * (py[k] + uy[k] - cy + lambda * gradient[k][1]);
        g[k * 3 + 2][j] = w * (pz[k] + uz[k] - cz + lambda * gradient[k][2]);
      }
    }
    for (std::size_t j = 0; j < size; ++j)
      for (std::size_t k = 0; k < 6; ++k) {
        const std::size_t node = corner[k][begin + j];
        out[node] += NodeSum4{g[k * 3 + 0][j], g[k * 3 + 1][j], g[k * 3 + 2][j], 0.0f};
      }
  }
}

}  // namespace

void add_projections(const ProjectiveSystem& system, const NodeVectors& q, const NodeVectors& u, NodeSum4* out) {
  add_spring_projections(system, q, u, out);
  add_volume_projections(system, q, u, out);
}

}  // namespace fw::physics::detail
