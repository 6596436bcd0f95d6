// The mass-spring sub-step (Lee, Terzopoulos & Waters 1995; the behavioral-
// animation paper sec. 3.2): forces from the viscoelastic units, the volume
// preservation of every prism and the muscles, then one semi-implicit Euler
// step (velocity first, the medium's drag implicit so it can never
// overshoot), then the skull. Every pass walks flat arrays in order.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/physics/face_simulation.hpp"
#include "tissue_forces.hpp"

namespace fw::physics {
namespace {

// A safety net, far above anything a face does (1.3 m/s): a node pushed
// faster than this by a bad input is slowed instead of blowing up.
constexpr float kMaxSpeed = 20.0f;

}  // namespace

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
  const float weight = -options_.gravity * m.material.node_mass;
  std::fill(fx, fx + node_count, 0.0f);
  std::fill(fy, fy + node_count, weight);
  std::fill(fz, fz + node_count, 0.0f);

  // Viscoelastic units (stress_strain.hpp) and the volume preservation of
  // every prism (Lee et al. 1995, eq. 6: a push along the volume gradient in
  // proportion to the thickness lost), in tissue_forces.cpp.
  const detail::NodeArrays nodes{x, y, z, vx, vy, vz, fx, fy, fz};
  detail::add_spring_forces(m, detail::spring_kind_table(m.material), nodes);
  detail::add_volume_forces(m, nodes);

  detail::add_muscle_forces(m, {activation_, strength_, muscle_origins(), skull_normal_.data()}, nodes);

  // Semi-implicit Euler; the drag of the medium taken implicitly.
  // Pinned nodes (inverse mass 0) keep the speed place_bone gave them.
  const float* inverse_mass = m.explicit_inverse_mass.data();
  const float drag = 1.0f / (1.0f + h * m.material.node_damping);
  for (std::size_t i = 0; i < moving; ++i) {
    if (inverse_mass[i] == 0.0f) continue;
    const float step = h * inverse_mass[i];
    float ux = (vx[i] + step * fx[i]) * drag, uy = (vy[i] + step * fy[i]) * drag, uz = (vz[i] + step * fz[i]) * drag;
    const float speed2 = ux * ux + uy * uy + uz * uz;
    if (speed2 > kMaxSpeed * kMaxSpeed) {
      const float s = kMaxSpeed / std::sqrt(speed2);
      ux *= s, uy *= s, uz *= s;
    }
    vx[i] = ux, vy[i] = uy, vz[i] = uz;
    x[i] += h * ux, y[i] += h * uy, z[i] += h * uz;
  }
  resolve_skull();
  // Measured after the skull took away what pressed into it: a node resting
  // on the bone is not moving.
  float max_speed2 = 0.0f;
  for (std::size_t i = 0; i < moving; ++i) max_speed2 = std::max(max_speed2, vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]);
  max_speed2_ = max_speed2;
}

}  // namespace fw::physics
