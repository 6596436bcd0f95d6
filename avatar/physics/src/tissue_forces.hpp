#pragma once
// The mass-spring solver's two hot loops as free kernels over flat arrays:
// the viscoelastic units and the prism volumes. Each walks its elements in
// blocks: first every element's force is computed into a small local block
// (no writes to shared nodes, so the compiler vectorises it, with gathers
// where the CPU has them), then the block is added onto the nodes.
#include <array>
#include <cstddef>

#include <glm/vec3.hpp>

#include "fw/physics/muscle_course.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::physics::detail {

/// One array over the nodes per axis.
template <typename T>
struct NodeAxes {
  T* x;
  T* y;
  T* z;
};

struct NodeArrays {
  const float* x;
  const float* y;
  const float* z;
  const float* vx;
  const float* vy;
  const float* vz;
  float* fx;
  float* fy;
  float* fz;
};

/// Per spring kind: F = k1 (max(0, d) + share min(0, d)) + k2_extra max(0, L - knee L0) + c dL/dt,
/// d = L - slack L0 (stress_strain.hpp).
struct SpringKindTable {
  float k1[kSpringKindCount];
  float compression_share[kSpringKindCount];
  float k2_extra[kSpringKindCount];
  float slack[kSpringKindCount];
  float knee[kSpringKindCount];
  float damping[kSpringKindCount];
};
SpringKindTable spring_kind_table(const TissueMaterial& material);

/// A unit's elastic force (tension positive) at `length`, rest length `rest`.
inline float elastic_force(const SpringKindTable& t, std::size_t kind, float length, float rest) {
  const float from_natural = length - rest * t.slack[kind];
  return t.k1[kind] * (from_natural > 0.0f ? from_natural : 0.0f) +
         t.k1[kind] * t.compression_share[kind] * (from_natural < 0.0f ? from_natural : 0.0f) +
         t.k2_extra[kind] * (length > rest * t.knee[kind] ? length - rest * t.knee[kind] : 0.0f);
}

void add_spring_forces(const TissueModel& model, const SpringKindTable& table, const NodeArrays& nodes);
void add_volume_forces(const TissueModel& model, const NodeArrays& nodes);

/// What drives the muscles now: activation x strength, each muscle's origin
/// where the jaw has carried it, the skull normals turned with the jaw, and
/// the face's own weight on each attachment (its course, muscle_course.hpp).
struct MuscleDrive {
  const std::array<float, kMuscleCount>& activation;
  const std::array<float, kMuscleCount>& strength;
  const std::array<glm::vec3, kMuscleCount>& origin;
  const glm::vec3* skull_normal;  ///< #V
  const MuscleCourse& course;     ///< the nodes each muscle pulls, and how much
};
/// Each node the face's course attaches pulled toward its muscle's origin (linear, along the
/// skull) or centre (sphincter) by activation x strength x profile weight.
void add_muscle_forces(const TissueModel& model, const MuscleDrive& drive, const NodeArrays& nodes);

}  // namespace fw::physics::detail
