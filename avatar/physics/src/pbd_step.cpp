// The position-based-dynamics sub-step (Müller et al. 2007; the PBD face of
// the motion-cloning thesis, ch. 5): predict positions from the velocities,
// project the constraints Gauss-Seidel style (muscles, distances, skin
// areas, prism volumes), keep the tissue out of the skull, and take the
// velocities from the corrected positions. Stiffnesses are normalised to
// [0,1]; a muscle contracts by re-sampling its action line with its
// normalised activation, which moves each attached node's goal toward the
// origin.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/physics/distance_constraint.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/prism_volume.hpp"

namespace fw::physics {
namespace {

// PBD stiffness of a unit from its mass-spring slope: k / (k + kReference),
// so both solvers keep the same ordering of stiff and soft tissue.
constexpr float kReferenceStiffness = 1500.0f;
constexpr float kVolumeStiffness = 0.8f;
constexpr float kAreaStiffness = 0.2f;
constexpr float kMuscleStiffness = 0.5f;
// How far a muscle moves its goals per unit of force: calibrated so that a
// PBD action unit is about as large as the mass-spring one.
constexpr float kMuscleCompliance = 1.0f / 500.0f;
constexpr float kVelocityDamping = 10.0f;  // 1/s

}  // namespace

void FaceSimulation::pbd_substep(float h) {
  const TissueModel& m = *model_;
  const std::size_t moving = m.moving_node_count;
  float* __restrict x = x_.data();
  float* __restrict y = y_.data();
  float* __restrict z = z_.data();
  float* __restrict px = fx_.data();  // previous positions
  float* __restrict py = fy_.data();
  float* __restrict pz = fz_.data();
  const float drag = 1.0f / (1.0f + h * kVelocityDamping);
  const float* inverse_masses = m.inverse_mass.data();
  for (std::size_t i = 0; i < moving; ++i) {
    px[i] = x[i], py[i] = y[i], pz[i] = z[i];
    if (inverse_masses[i] == 0.0f) continue;  // pinned: placed by place_bone
    vy_[i] -= h * options_.gravity;
    vx_[i] *= drag, vy_[i] *= drag, vz_[i] *= drag;
    x[i] += h * vx_[i], y[i] += h * vy_[i], z[i] += h * vz_[i];
  }
  auto inverse_mass = [&](std::size_t node) { return node < moving ? inverse_masses[node] : 0.0f; };
  auto at = [&](std::size_t node) { return glm::vec3(x[node], y[node], z[node]); };
  auto move = [&](std::size_t node, const glm::vec3& d) { x[node] += d.x, y[node] += d.y, z[node] += d.z; };

  std::array<float, kSpringKindCount> stiffness{};
  for (std::size_t k = 0; k < kSpringKindCount; ++k) {
    const float s = m.material.curves[k].stiffness;
    stiffness[k] = s / (s + kReferenceStiffness);
  }

  for (int iteration = 0; iteration < std::max(1, options_.pbd_iterations); ++iteration) {
    // Muscles: goal = rest + the bone's own motion + the contraction.
    for (std::size_t i = 0; i < kMuscleCount; ++i) {
      const float a = activation_[i];
      const TissueMuscle& muscle = m.muscles[i];
      if (a < 1e-5f || muscle.first == muscle.last) continue;
      const float reach = a * strength_[i] * kMuscleCompliance;
      const glm::vec3 o = muscle.origin_jaw_share > 0.0f ? jaw_turned(muscle.origin, muscle.origin_jaw_share) : muscle.origin;
      const glm::vec3 scale = muscle.kind == MuscleKind::sphincter ? muscle.pull_scale : glm::vec3(1.0f);
      for (std::uint32_t t = muscle.first; t < muscle.last; ++t) {
        const std::size_t n = m.attach_node[t];
        if (inverse_masses[n] == 0.0f) continue;
        const std::size_t b = moving + m.attach_column[t];
        const glm::vec3 rest(m.rest_x[n], m.rest_y[n], m.rest_z[n]);
        const glm::vec3 bone_shift = at(b) - glm::vec3(m.rest_x[b], m.rest_y[b], m.rest_z[b]);
        glm::vec3 line = o - rest;
        if (muscle.kind == MuscleKind::linear) {
          const glm::vec3& normal = m.skull_normal[m.attach_column[t]];
          line -= glm::dot(line, normal) * normal;
        }
        const float length = glm::length(line);
        if (length < 1e-6f) continue;
        const glm::vec3 goal = rest + bone_shift + (line * scale) * (reach * m.attach_weight[t] / length);
        move(n, kMuscleStiffness * (goal - at(n)));
      }
    }
    // Distances: every viscoelastic unit, the bending units included.
    for (std::size_t s = 0; s < m.spring_count(); ++s) {
      const std::size_t a = m.spring_a[s], b = m.spring_b[s];
      glm::vec3 ca, cb;
      if (!solve_distance(at(a), inverse_mass(a), at(b), inverse_mass(b), m.spring_rest[s],
                          stiffness[static_cast<std::size_t>(m.spring_kind[s])], ca, cb))
        continue;
      move(a, ca);
      move(b, cb);
    }
    // Skin areas: C = A - A0, grad_a A = (b - c) x n / 2 and cyclically.
    for (std::size_t t = 0; t < m.skin_triangles.size(); ++t) {
      const glm::uvec3 tri = m.skin_triangles[t];
      const glm::vec3 a = at(tri[0]), b = at(tri[1]), c = at(tri[2]);
      const glm::vec3 normal = glm::cross(b - a, c - a);
      const float twice_area = glm::length(normal);
      if (twice_area < 1e-12f) continue;
      const glm::vec3 n = normal / twice_area;
      const glm::vec3 g[3] = {0.5f * glm::cross(b - c, n), 0.5f * glm::cross(c - a, n), 0.5f * glm::cross(a - b, n)};
      float denominator = 0.0f;
      for (int k = 0; k < 3; ++k) denominator += inverse_mass(tri[k]) * glm::dot(g[k], g[k]);
      if (denominator < 1e-12f) continue;
      const float lambda = -kAreaStiffness * (0.5f * twice_area - m.skin_rest_area[t]) / denominator;
      for (int k = 0; k < 3; ++k) move(tri[k], lambda * inverse_mass(tri[k]) * g[k]);
    }
    // Prism volumes: C = V - V0, dp_i = -s C w_i grad_i / sum_j w_j |grad_j|^2.
    for (std::size_t e = 0; e < m.element_count(); ++e) {
      const auto nodes = m.element(e);
      PrismNodes p, gradient;
      for (std::size_t k = 0; k < 6; ++k) p[k] = at(nodes[k]);
      const float volume = prism_volume(p, &gradient);
      float denominator = 0.0f;
      for (std::size_t k = 0; k < 6; ++k) denominator += inverse_mass(nodes[k]) * glm::dot(gradient[k], gradient[k]);
      if (denominator < 1e-18f) continue;
      const float lambda = -kVolumeStiffness * (volume - m.element_rest_volume[e]) / denominator;
      for (std::size_t k = 0; k < 6; ++k) move(nodes[k], lambda * inverse_mass(nodes[k]) * gradient[k]);
    }
  }
  resolve_skull();
  const float inv_h = 1.0f / h;
  float max_speed2 = 0.0f;
  for (std::size_t i = 0; i < moving; ++i) {
    vx_[i] = (x[i] - px[i]) * inv_h, vy_[i] = (y[i] - py[i]) * inv_h, vz_[i] = (z[i] - pz[i]) * inv_h;
    max_speed2 = std::max(max_speed2, vx_[i] * vx_[i] + vy_[i] * vy_[i] + vz_[i] * vz_[i]);
  }
  max_speed2_ = max_speed2;
}

}  // namespace fw::physics
