// The mass-spring sub-step (Lee, Terzopoulos & Waters 1995; the behavioral-
// animation paper sec. 3.2): forces from the viscoelastic units, the volume
// preservation of every prism and the muscles, then one semi-implicit Euler
// step (velocity first, the tissue's viscous bond to the bone under it
// implicit so it can never overshoot), then the skull. The sub-step is the
// plain masses' stable bound (no mass scaling) and nothing limits a node's
// speed. Every pass walks flat arrays in order.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/physics/face_simulation.hpp"
#include "tissue_forces.hpp"

namespace fw::physics {
void FaceSimulation::mass_spring_substep(float h) {
  const TissueModel& m = *model_;
  const std::size_t node_count = m.node_count, moving = m.moving_node_count;
  float* __restrict x = x_.data();
  float* __restrict y = y_.data();
  float* __restrict z = z_.data();
  float* __restrict vx = vx_.data();
  float* __restrict vy = vy_.data();
  float* __restrict vz = vz_.data();
  float* __restrict fx = fx_.data();
  float* __restrict fy = fy_.data();
  float* __restrict fz = fz_.data();
  // The head's load and any extra gravity (head_loads.hpp).
  fill_load_forces(load_, m.material.node_mass, node_count, x, y, z, fx, fy, fz);

  // Viscoelastic units (stress_strain.hpp) and the volume preservation of
  // every prism (Lee et al. 1995, eq. 6: a push along the volume gradient in
  // proportion to the thickness lost), in tissue_forces.cpp.
  const detail::NodeArrays nodes{x, y, z, vx, vy, vz, fx, fy, fz};
  detail::add_spring_forces(m, detail::spring_kind_table(m.material), nodes);
  detail::add_volume_forces(m, nodes);

  detail::add_muscle_forces(m, {activation_, strength_, muscle_origins(), skull_normal_.data(), course_}, nodes);

  // Semi-implicit Euler. Each node is damped against the bone of its own
  // column (relative speed, implicit): the tissue's viscous bond to the
  // skull and mandible, not a drag of the world frame, so tissue carried by
  // the turning jaw keeps up with it. Pinned nodes (inverse mass 0) keep the
  // speed place_bone gave them.
  const float* inverse_mass = m.inverse_mass.data();
  const float hc = h * m.material.bone_damping;
  const float keep = 1.0f / (1.0f + hc);
  const std::size_t nv = m.vertex_count;
  for (std::size_t layer = 0; layer < kMovingLayerCount; ++layer) {
    const std::size_t first = layer * nv;
    for (std::size_t v = 0; v < nv; ++v) {
      const std::size_t i = first + v, b = moving + v;
      if (inverse_mass[i] == 0.0f) continue;
      const float step = h * inverse_mass[i];
      const float ux = (vx[i] + step * fx[i] + hc * vx[b]) * keep;
      const float uy = (vy[i] + step * fy[i] + hc * vy[b]) * keep;
      const float uz = (vz[i] + step * fz[i] + hc * vz[b]) * keep;
      vx[i] = ux, vy[i] = uy, vz[i] = uz;
      x[i] += h * ux, y[i] += h * uy, z[i] += h * uz;
    }
  }
  resolve_contacts();
  // Measured after the skull took away what pressed into it: a node resting
  // on the bone is not moving.
  float max_speed2 = 0.0f;
  for (std::size_t i = 0; i < moving; ++i) max_speed2 = std::max(max_speed2, vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]);
  max_speed2_ = max_speed2;
}

}  // namespace fw::physics
