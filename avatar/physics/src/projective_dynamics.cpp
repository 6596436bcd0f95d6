#include "projective_dynamics.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <memory>
#include <vector>

#include "projective_local_step.hpp"
#include "projective_system.hpp"
#include "tissue_forces.hpp"

namespace fw::physics {
namespace {

using detail::kMaxBatchFaces;

// Per thread, reused: a pool thread steps batch after batch.
struct Scratch {
  std::vector<float> rows;                                     // free rows x lanes
  std::vector<float> constant[kMaxBatchFaces][3];              // per face, per axis, #nodes
  std::vector<float> u[kMaxBatchFaces][3];                     // per face, per axis, #nodes
  std::vector<float> sum[3];                                   // #nodes
  std::vector<detail::NodeSum4> projected;                     // #nodes: constant plus the projections (one face)
  // A batch's faces interleaved as the rows are, [(node * 3 + axis) * W + face]:
  std::vector<float> q_lanes, u_lanes, constant_lanes, sum_lanes;  // #nodes x lanes
};

Scratch& scratch_for(std::size_t nodes, std::size_t rows, std::size_t faces) {
  thread_local Scratch s;
  s.rows.resize(rows);  // every lane of every row is written before the solve (a padding lane repeats a face)
  for (std::size_t f = 0; f < faces; ++f) {
    for (auto& v : s.constant[f]) v.resize(nodes);
    for (auto& v : s.u[f]) v.resize(nodes);
  }
  for (auto& v : s.sum) v.resize(nodes);
  if (faces == 1) {
    s.projected.resize(nodes);
  } else {
    const std::size_t lanes = detail::lanes_for(faces);
    for (auto* v : {&s.q_lanes, &s.u_lanes, &s.constant_lanes, &s.sum_lanes}) v->resize(nodes * lanes);
  }
  return s;
}

}  // namespace

void ProjectiveStepper::step(std::span<FaceSimulation* const> faces, double dt_seconds) {
  struct Moving {
    FaceSimulation* face;
    double dt;
    int substeps;
  };
  std::vector<Moving> moving;
  for (FaceSimulation* face : faces) {
    assert(face->options().solver == Solver::projective);
    double dt = dt_seconds;
    const int n = face->begin_step(dt);
    if (n > 0) moving.push_back({face, dt, n});
  }
  std::stable_sort(moving.begin(), moving.end(), [](const Moving& a, const Moving& b) {
    const TissueModel *ma = factor_owner(*a.face), *mb = factor_owner(*b.face);
    return ma != mb ? ma < mb : a.substeps < b.substeps;
  });
  std::vector<FaceSimulation*> batch;
  for (std::size_t begin = 0; begin < moving.size();) {
    std::size_t end = begin + 1;
    while (end < moving.size() && end - begin < kMaxBatchFaces && factor_owner(*moving[end].face) == factor_owner(*moving[begin].face) &&
           moving[end].substeps == moving[begin].substeps)
      ++end;
    batch.clear();
    for (std::size_t i = begin; i < end; ++i) batch.push_back(moving[i].face);
    const float h = static_cast<float>(moving[begin].dt / moving[begin].substeps);
    for (int i = 0; i < moving[begin].substeps; ++i) substep(batch, h);
    for (FaceSimulation* face : batch) face->update_rest_state();
    begin = end;
  }
}

float ProjectiveStepper::tissue_step(float h) {
  constexpr double kGrid = 1.02;
  const double steps = std::round(std::log(double(h) / kFrameStepS) / std::log(kGrid));
  return static_cast<float>(kFrameStepS * std::pow(kGrid, steps));
}

void ProjectiveStepper::substep(std::span<FaceSimulation* const> faces, float h) {
  assert(!faces.empty() && faces.size() <= kMaxBatchFaces);
  // Each face's own constraints (its rest shape), one factor for all.
  const float step = tissue_step(h);
  std::array<std::shared_ptr<const detail::ProjectiveSystem>, kMaxBatchFaces> systems;
  for (std::size_t f = 0; f < faces.size(); ++f)
    systems[f] = faces[f]->model().projective_systems.get(faces[f]->model(), step);
  const detail::ProjectiveSystem& system = *systems[0];
  const TissueModel& m = faces.front()->model();  // its topology and material are every face's
  const std::size_t nodes = m.node_count, moving = m.moving_node_count;
  const std::size_t lanes = detail::lanes_for(faces.size()), width = lanes / 3;
  const std::vector<std::int32_t>& row_of = system.row_of_node();
  const std::vector<std::uint16_t>& free_nodes = system.free_nodes();
  const std::vector<std::uint16_t>& free_in_order = system.free_nodes_in_order();
  Scratch& s = scratch_for(nodes, system.free_count() * lanes, faces.size());
  const float mass = m.material.node_mass, beta = system.damping_s();
  // The tissue steps by the system's h, the muscles and the bone by the
  // frame's (tissue_step).
  const float ht = system.step_s();
  const float inertia = mass / (ht * ht);
  // Each moving node's viscous bond to the bone of its column, on their
  // relative speed (TissueMaterial::bone_damping, as the mass-spring and
  // XPBD solvers have it): implicitly, c M / h (x - x_n - the bone's move
  // this step) = 0 joins the system, so tissue on the turning mandible
  // keeps up with it: 99 ms after the open jaw is let go, the lower lip
  // trails its bone by 7.0 mm (mass-spring 5.7; without the bond 11.4:
  // projective_dynamics_test.cpp).
  const float bond = mass * m.material.bone_damping / ht;
  const std::size_t vertices = m.vertex_count;

  // Per face: the bone moves, the muscles pull; the part of the right-hand
  // side that the iterations do not change, and the inertial prediction as
  // the first guess.
  for (std::size_t f = 0; f < faces.size(); ++f) {
    FaceSimulation& face = *faces[f];
    assert(systems[f]->factor() == system.factor());
    float* x = face.x_.data();
    float* y = face.y_.data();
    float* z = face.z_.data();
    float* vx = face.vx_.data();
    float* vy = face.vy_.data();
    float* vz = face.vz_.data();
    float* px = face.fx_.data();  // the previous positions, as in PBD
    float* py = face.fy_.data();
    float* pz = face.fz_.data();
    std::copy(x, x + nodes, px), std::copy(y, y + nodes, py), std::copy(z, z + nodes, pz);
    face.update_muscles_and_jaw(h);
    face.place_bone(h);
    // u = (beta / h) x_n - (1 + beta / h) [prescribed positions now]: L u,
    // added with the projections, carries the damping of the last
    // positions and the pull of the prescribed nodes into the free rows.
    const float damp = beta / ht, hold = 1.0f + beta / ht;
    for (std::size_t i = 0; i < nodes; ++i) {
      const bool held = row_of[i] < 0;
      s.u[f][0][i] = damp * px[i] - (held ? hold * x[i] : 0.0f);
      s.u[f][1][i] = damp * py[i] - (held ? hold * y[i] : 0.0f);
      s.u[f][2][i] = damp * pz[i] - (held ? hold * z[i] : 0.0f);
    }
    auto& c = s.constant[f];  // read in the free rows only
    // External forces at the start of the step: the head's load (and any
    // extra gravity, head_loads.hpp), then the muscles.
    fill_load_forces(face.load_, mass, nodes, x, y, z, s.sum[0].data(), s.sum[1].data(), s.sum[2].data());
    detail::add_muscle_forces(face.model(), {face.activation_, face.strength_, face.muscle_origins(), face.skull_normal_.data(),
                               face.course_},
                              {x, y, z, vx, vy, vz, s.sum[0].data(), s.sum[1].data(), s.sum[2].data()});
    for (const std::uint16_t i : free_in_order) {
      // M s / h^2 with s = x + h v + h^2 f / m. The first guess is x + h v,
      // not s: a face held still by its muscles then starts every step from
      // where it is, so the few iterations end at the exact equilibrium
      // instead of short of it by what the force moves s.
      const float gx = x[i] + ht * vx[i], gy = y[i] + ht * vy[i], gz = z[i] + ht * vz[i];
      const std::size_t b = moving + i % vertices;  // its column's bone, moved by place_bone
      const float bx = px[i] + x[b] - px[b], by = py[i] + y[b] - py[b], bz = pz[i] + z[b] - pz[b];
      c[0][i] = inertia * gx + bond * bx + s.sum[0][i];
      c[1][i] = inertia * gy + bond * by + s.sum[1][i];
      c[2][i] = inertia * gz + bond * bz + s.sum[2][i];
      x[i] = gx, y[i] = gy, z[i] = gz;
    }
  }

  // A batch's local steps run across its faces: each node's values of every
  // face side by side, as the solve's rows hold them (padding lanes repeat
  // the first face).
  std::array<const detail::ProjectiveSystem*, kMaxBatchFaces> lane_systems{};
  std::array<detail::NodeVectors, kMaxBatchFaces> face_q{}, face_u{};
  // Written in order, a run of `width` values at a time (one face after
  // another wrote a value per cache line).
  auto interleave = [&](float* lanes_out, auto&& source) {
    std::array<const float*, 3 * kMaxBatchFaces> from;
    for (std::size_t axis = 0; axis < 3; ++axis)
      for (std::size_t lane = 0; lane < width; ++lane) from[axis * width + lane] = source(lane < faces.size() ? lane : 0, axis);
    for (std::size_t i = 0; i < nodes; ++i)
      for (std::size_t k = 0; k < lanes; ++k) lanes_out[i * lanes + k] = from[k][i];
  };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    face_q[f] = {faces[f]->x_.data(), faces[f]->y_.data(), faces[f]->z_.data()};
    face_u[f] = {s.u[f][0].data(), s.u[f][1].data(), s.u[f][2].data()};
  }
  if (faces.size() > 1) {
    for (std::size_t lane = 0; lane < width; ++lane) lane_systems[lane] = systems[lane < faces.size() ? lane : 0].get();
    interleave(s.u_lanes.data(), [&](std::size_t f, std::size_t axis) { return s.u[f][axis].data(); });
    interleave(s.constant_lanes.data(), [&](std::size_t f, std::size_t axis) { return s.constant[f][axis].data(); });
  }

  for (int iteration = 0; iteration < kIterations; ++iteration) {
    // Local: every constraint projects each face's positions.
    if (faces.size() == 1) {
      const auto& c = s.constant[0];
      for (std::size_t i = 0; i < nodes; ++i) s.projected[i] = detail::NodeSum4{c[0][i], c[1][i], c[2][i], 0.0f};
      detail::add_projections(system, face_q[0], face_u[0], s.projected.data());
      for (std::size_t r = 0; r < free_nodes.size(); ++r) {
        float* row = s.rows.data() + r * lanes;
        const detail::NodeSum4& sum = s.projected[free_nodes[r]];
        row[0] = sum[0], row[1] = sum[1], row[2] = sum[2];
      }
    } else {
      interleave(s.q_lanes.data(), [&](std::size_t f, std::size_t axis) {
        return axis == 0 ? face_q[f].x : axis == 1 ? face_q[f].y : face_q[f].z;
      });
      std::copy(s.constant_lanes.begin(), s.constant_lanes.end(), s.sum_lanes.begin());
      detail::add_projections_across(std::span(lane_systems.data(), width), s.q_lanes.data(), s.u_lanes.data(), s.sum_lanes.data());
      // A free node's sums are its row, as they are laid out.
      for (std::size_t r = 0; r < free_nodes.size(); ++r) {
        const float* sum = s.sum_lanes.data() + std::size_t(free_nodes[r]) * lanes;
        std::copy(sum, sum + lanes, s.rows.data() + r * lanes);
      }
    }
    // Global: one solve for all faces and axes.
    system.solve(s.rows.data(), lanes);
    // Read in order, a row at a time, as interleave writes.
    std::array<float*, 3 * kMaxBatchFaces> to;
    for (std::size_t f = 0; f < faces.size(); ++f)
      to[f] = faces[f]->x_.data(), to[width + f] = faces[f]->y_.data(), to[2 * width + f] = faces[f]->z_.data();
    for (std::size_t r = 0; r < free_nodes.size(); ++r) {
      const float* row = s.rows.data() + r * lanes;
      const std::size_t i = free_nodes[r];
      for (std::size_t axis = 0; axis < 3; ++axis)
        for (std::size_t f = 0; f < faces.size(); ++f) to[axis * width + f][i] = row[axis * width + f];
    }
  }

  // Velocities from the positions (implicit Euler), then the skull and the
  // lips.
  const float inv_h = 1.0f / ht;
  for (FaceSimulation* face : faces) {
    for (const std::uint16_t i : free_in_order) {
      face->vx_[i] = (face->x_[i] - face->fx_[i]) * inv_h;
      face->vy_[i] = (face->y_[i] - face->fy_[i]) * inv_h;
      face->vz_[i] = (face->z_[i] - face->fz_[i]) * inv_h;
    }
    face->resolve_contacts();
    float max_speed2 = 0.0f;
    for (std::size_t i = 0; i < moving; ++i)
      max_speed2 = std::max(max_speed2, face->vx_[i] * face->vx_[i] + face->vy_[i] * face->vy_[i] + face->vz_[i] * face->vz_[i]);
    face->max_speed2_ = max_speed2;
  }
}

}  // namespace fw::physics
