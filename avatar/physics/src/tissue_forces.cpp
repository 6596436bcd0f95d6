#include "tissue_forces.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "hot_clones.hpp"
#include "bulk_curve.hpp"
#include "wedge_volume.hpp"

namespace fw::physics::detail {
namespace {

constexpr std::size_t kBlock = 128;


}  // namespace

SpringKindTable spring_kind_table(const TissueMaterial& material) {
  SpringKindTable t{};
  for (std::size_t k = 0; k < kSpringKindCount; ++k) {
    const StressStrainCurve& c = material.curves[k];
    t.k1[k] = c.stiffness;
    t.compression_share[k] = c.compression_share;
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
      const float force = elastic_force(table, kind, length, rest[s]) + table.damping[kind] * speed;
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
  const float knee = model.material.volume_knee, extra = model.material.volume_stiff_ratio - 1.0f;
  const std::size_t count = model.element_count();
  const std::uint16_t* corner[6];
  for (std::size_t k = 0; k < 6; ++k) corner[k] = model.element_node[k].data();
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
      float gradient[6][3];
      const float volume = wedge_volume_gradient(px, py, pz, gradient);
      const float rest = model.element_rest_volume[e];
      const float f = stiffness * restoring_volume(rest - volume, rest, knee, extra) * model.element_force_scale[e];
#pragma GCC unroll 6
      for (int k = 0; k < 6; ++k)
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) g[k * 3 + c][j] = f * gradient[k][c];
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

void add_muscle_forces(const TissueModel& m, const MuscleDrive& drive, const NodeArrays& n) {
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    const float a = drive.activation[i];
    const TissueMuscle& muscle = m.muscles[i];
    const AttachmentSpan span = muscle_attachments(m, drive.course, i);
    if (a < 1e-5f || span.count == 0) continue;
    const float pull = a * drive.strength[i];
    const glm::vec3 o = drive.origin[i];
    const glm::vec3 scale = muscle.kind == MuscleKind::sphincter ? muscle.pull_scale : glm::vec3(1.0f);
    const bool slides = muscle.kind == MuscleKind::linear;
    for (std::uint32_t t = 0; t < span.count; ++t) {
      const std::size_t node = span.node[t];
      glm::vec3 d(o.x - n.x[node], o.y - n.y[node], o.z - n.z[node]);
      // A linear muscle's fibres run along the skull: the tissue is pulled
      // along the bone surface, not into it.
      if (slides) {
        const glm::vec3& normal = drive.skull_normal[span.column[t]];
        d -= glm::dot(d, normal) * normal;
      }
      const float length = glm::length(d);
      if (length < 1e-6f) continue;
      const glm::vec3 f = (pull * span.weight[t] / length) * (d * scale);
      n.fx[node] += f.x, n.fy[node] += f.y, n.fz[node] += f.z;
    }
  }
}

}  // namespace fw::physics::detail
