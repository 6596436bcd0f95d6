// The XPBD sub-step (Macklin, Müller & Chentanez 2016, "XPBD: Position-Based
// Simulation of Compliant Constrained Dynamics"; the PBD face paper's
// constraints and muscles). Positions are predicted from the velocities,
// then every constraint is projected Gauss-Seidel style with its compliance
// alpha (the inverse of a stiffness taken from the tissue material) scaled
// by 1/h^2 and its Lagrange multiplier accumulated over the iterations:
//
//   dlambda = (-C - alpha~ lambda - gamma grad C . (x - x_prev)) / ((1 + gamma) sum w |grad C|^2 + alpha~),
//   alpha~ = alpha / h^2, gamma = alpha~ beta~ / h, beta~ = h^2 beta (sec. 3.5's damping),
//
// so the tissue's stiffness does not change with the step or the number of
// iterations, as it did when PBD scaled each correction by a stiffness in
// [0,1]. Constraints: the muscles' ties (each attached node to the point of
// its muscle's action line it lies beside, muscle_particles.hpp), every
// viscoelastic unit (distance, at the secant slope of its stress-strain
// curve so that a converged unit pulls with the curve's force; its damper as
// XPBD damping) and every prism's volume (the mass-spring solver's volume
// stiffness). Then the skull, the velocities from the positions, and the
// tissue's viscous bond to the bone (the mass-spring solver's, implicit).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "fw/physics/face_simulation.hpp"
#include "fw/physics/prism_volume.hpp"
#include "bulk_curve.hpp"
#include "tissue_forces.hpp"

namespace fw::physics {
namespace {

// Scratch shared by the faces one thread steps: the multipliers (reset
// every sub-step) and the muscle particles' places.
struct XpbdScratch {
  std::vector<float> lambda;
  std::vector<glm::vec3> move, particle, tie_target;
  std::vector<float> tie_compliance;
  std::vector<std::uint16_t> tie_node;  ///< each tie's node, the face's muscles in order
  std::vector<float> tie_weight;
};
XpbdScratch& scratch() {
  thread_local XpbdScratch s;
  return s;
}

// The least tie stiffness times h^2 that holds: 1e-12 of a unit tie's.
constexpr float kLeastTieStiffness = 1e-12f;

}  // namespace

void FaceSimulation::pbd_substep(float h, const std::array<float, kMuscleCount>& activation) {
  const TissueModel& m = *model_;
  // This face's muscles: its own particles where its course moved them.
  const MuscleParticles& mp = course_.own_particles ? course_.particles : m.muscle_particles;
  const std::size_t moving = m.moving_node_count;
  float* __restrict x = x_.data();
  float* __restrict y = y_.data();
  float* __restrict z = z_.data();
  float* __restrict px = fx_.data();  // previous positions
  float* __restrict py = fy_.data();
  float* __restrict pz = fz_.data();
  const float* inverse_masses = m.inverse_mass.data();
  for (std::size_t i = 0; i < m.node_count; ++i) px[i] = x[i], py[i] = y[i], pz[i] = z[i];
  for (std::size_t i = 0; i < moving; ++i) {
    if (inverse_masses[i] == 0.0f) continue;  // pinned: placed by place_bone
    const glm::vec3 a = load_.at({x[i], y[i], z[i]});  // the head's load and any extra gravity
    vx_[i] += h * a.x, vy_[i] += h * a.y, vz_[i] += h * a.z;
    x[i] += h * vx_[i], y[i] += h * vy_[i], z[i] += h * vz_[i];
  }
  auto inverse_mass = [&](std::size_t node) { return node < moving ? inverse_masses[node] : 0.0f; };
  auto at = [&](std::size_t node) { return glm::vec3(x[node], y[node], z[node]); };
  auto before = [&](std::size_t node) { return glm::vec3(px[node], py[node], pz[node]); };
  auto move = [&](std::size_t node, const glm::vec3& d) { x[node] += d.x, y[node] += d.y, z[node] += d.z; };

  XpbdScratch& s = scratch();
  s.tie_node.clear();
  s.tie_weight.clear();
  for (std::size_t i = 0; i < kMuscleCount; ++i) {
    const AttachmentSpan span = muscle_attachments(m, course_, i);
    s.tie_node.insert(s.tie_node.end(), span.node, span.node + span.count);
    s.tie_weight.insert(s.tie_weight.end(), span.weight, span.weight + span.count);
  }
  const std::size_t ties = s.tie_node.size(), springs = m.spring_count(), elements = m.element_count();
  s.lambda.assign(ties + springs + 2 * elements, 0.0f);
  float* lambda_tie = s.lambda.data();
  float* lambda_spring = lambda_tie + ties;
  float* lambda_volume = lambda_spring + springs;
  float* lambda_knee = lambda_volume + elements;

  // Each muscle's action line re-sampled at its full contraction, each
  // particle riding the bone under it (the jaw carries the lower ones);
  // each tie's target is its point of the line plus the node's rest offset
  // from it, its stiffness the muscle's activation times the tie's own:
  // Hill's muscle, whose force is the activation times a force-length
  // relation (Zajac 1989), here falling linearly to nothing at full
  // contraction. An inactive muscle holds nothing.
  full_contraction(m, mp, course_.origin, s.move);
  s.particle.resize(mp.particle_count());
  for (std::size_t k = 0; k < mp.particle_count(); ++k) {
    const std::size_t bone = moving + mp.column[k];
    const glm::vec3 bone_shift = at(bone) - glm::vec3(m.rest_x[bone], m.rest_y[bone], m.rest_z[bone]);
    s.particle[k] = s.move[k] + bone_shift;  // the particle's move from rest
  }
  s.tie_target.resize(ties);
  s.tie_compliance.resize(ties);
  for (std::size_t t = 0; t < ties; ++t) {
    const std::size_t a = mp.tie_first[t], n = s.tie_node[t];
    const float share = mp.tie_share[t] * (1.0f / 255.0f);
    const glm::vec3 shift = share > 0.0f ? (1.0f - share) * s.particle[a] + share * s.particle[a + 1] : s.particle[a];
    s.tie_target[t] = glm::vec3(m.rest_x[n], m.rest_y[n], m.rest_z[n]) + shift;
    // The face's own muscle strength and course (individual variation).
    const std::size_t muscle = mp.muscle[a];
    const float stiffness = activation[muscle] * strength_[muscle] * tie_stiffness_per_strength(mp, s.move, t, s.tie_weight[t]);
    // 0: no tie. A muscle relaxing toward 0 passes activations so small
    // that 1 / (k h^2) would overflow (and inf times a multiplier of 0 is
    // NaN): such a tie holds nothing anyway.
    const float stiffness_h2 = stiffness * h * h;
    s.tie_compliance[t] = stiffness_h2 > kLeastTieStiffness ? 1.0f / stiffness_h2 : 0.0f;
  }

  const detail::SpringKindTable table = detail::spring_kind_table(m.material);
  const float inv_h2 = 1.0f / (h * h);
  for (int iteration = 0; iteration < std::max(1, options_.pbd_iterations); ++iteration) {
    // Ties: C = |x_n - target|, alpha = 1 / the tie's stiffness.
    for (std::size_t t = 0; t < ties; ++t) {
      const std::size_t n = s.tie_node[t];
      const float w = inverse_masses[n], alpha = s.tie_compliance[t];
      if (w == 0.0f || alpha == 0.0f) continue;
      const glm::vec3 d = at(n) - s.tie_target[t];
      const float c = glm::length(d);
      if (c < 1e-9f) continue;
      const float dl = (-c - alpha * lambda_tie[t]) / (w + alpha);
      lambda_tie[t] += dl;
      move(n, (dl * w / c) * d);
    }
    // Units: C = L - L_natural, alpha = 1 / the curve's secant slope now,
    // beta = the unit's damper.
    for (std::size_t u = 0; u < springs; ++u) {
      const std::size_t a = m.spring_a[u], b = m.spring_b[u];
      const float wa = inverse_mass(a), wb = inverse_mass(b);
      if (wa + wb == 0.0f) continue;
      const auto kind = static_cast<std::size_t>(m.spring_kind[u]);
      const glm::vec3 d = at(a) - at(b);
      const float length = glm::length(d);
      if (length < 1e-9f) continue;
      const float c = length - m.spring_rest[u] * table.slack[kind];
      const float force = detail::elastic_force(table, kind, length, m.spring_rest[u]);
      if (std::abs(c) < 1e-12f || force == 0.0f) continue;  // slack (tension-only skin)
      const float stiffness = force / c;
      const glm::vec3 n = d / length;
      const float alpha = inv_h2 / stiffness;
      const float gamma = alpha * table.damping[kind] * h;  // alpha~ beta~ / h
      const float rate = glm::dot(n, (at(a) - before(a)) - (at(b) - before(b)));
      const float dl = (-c - alpha * lambda_spring[u] - gamma * rate) / ((1.0f + gamma) * (wa + wb) + alpha);
      lambda_spring[u] += dl;
      move(a, (dl * wa) * n);
      move(b, (-dl * wb) * n);
    }
    // Prism volumes: C = V - V0, alpha = 1 / (volume stiffness x the
    // element's thickness scale), as the mass-spring solver's force; past
    // the bulk curve's knee a second constraint on the part beyond it, at
    // the stiffer slope's extra share (bulk_curve.hpp), so the two add up
    // to the mass-spring solver's curve.
    const float knee = m.material.volume_knee, extra = m.material.volume_stiff_ratio - 1.0f;
    for (std::size_t e = 0; e < elements; ++e) {
      const auto nodes = m.element(e);
      PrismNodes p, gradient;
      for (std::size_t k = 0; k < 6; ++k) p[k] = at(nodes[k]);
      const float c = prism_volume(p, &gradient) - m.element_rest_volume[e];
      float denominator = 0.0f;
      for (std::size_t k = 0; k < 6; ++k) denominator += inverse_mass(nodes[k]) * glm::dot(gradient[k], gradient[k]);
      if (denominator < 1e-18f) continue;
      const float alpha = inv_h2 / (m.material.volume_stiffness * m.element_force_scale[e]);
      const float dl = (-c - alpha * lambda_volume[e]) / (denominator + alpha);
      lambda_volume[e] += dl;
      float dk = 0.0f;
      if (extra > 0.0f) {
        // The change after this move, to first order: the move is dl w grad V.
        const float beyond = -detail::volume_beyond_knee(-(c + dl * denominator), m.element_rest_volume[e], knee);
        const float alpha_knee = alpha / extra;
        dk = (-beyond - alpha_knee * lambda_knee[e]) / (denominator + alpha_knee);
        lambda_knee[e] += dk;
      }
      for (std::size_t k = 0; k < 6; ++k) move(nodes[k], (dl + dk) * inverse_mass(nodes[k]) * gradient[k]);
    }
  }
  resolve_contacts();
  // Velocities from the positions, then the bond to the bone of each
  // column (relative speed, implicit), as in the mass-spring solver.
  const float inv_h = 1.0f / h;
  // Exact decay of the relative speed over the step, exp(-h c), written
  // as the implicit update v = (v_free + hc v_bone) / (1 + hc) with hc
  // chosen to match it, so that long and short steps damp alike.
  const float keep = std::exp(-h * m.material.bone_damping);
  const float hc = 1.0f / keep - 1.0f;
  const std::size_t nv = m.vertex_count;
  float max_speed2 = 0.0f;
  for (std::size_t i = 0; i < moving; ++i) {
    if (inverse_masses[i] != 0.0f) {  // a pinned node keeps the speed place_bone gave it
      const std::size_t b = moving + i % nv;
      vx_[i] = ((x[i] - px[i]) * inv_h + hc * vx_[b]) * keep;
      vy_[i] = ((y[i] - py[i]) * inv_h + hc * vy_[b]) * keep;
      vz_[i] = ((z[i] - pz[i]) * inv_h + hc * vz_[b]) * keep;
    }
    max_speed2 = std::max(max_speed2, vx_[i] * vx_[i] + vy_[i] * vy_[i] + vz_[i] * vz_[i]);
  }
  max_speed2_ = max_speed2;
}

}  // namespace fw::physics
