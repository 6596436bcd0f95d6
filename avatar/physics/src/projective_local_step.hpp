#pragma once
// The local step of projective dynamics (Bouaziz et al. 2014, sec. 3-4) and
// the constraint operator L = sum w A^T A, over flat node arrays: each
// constraint's projection of the current positions, weighted and summed
// into the right-hand side of the global step.
#include <cstddef>
#include <span>

#include "projective_system.hpp"
#include "tissue_forces.hpp"

namespace fw::physics::detail {

using NodeVectors = NodeAxes<const float>;

/// A node's sum as x, y, z and a lane of padding: a constraint adds its pull
/// onto a node with one 16-byte load, add and store where three scattered
/// arrays took three of each (the scatter was two fifths of the local step).
using NodeSum4 = float __attribute__((vector_size(16)));

/// out += sum over constraints of w A^T (p + A u): p the constraint's
/// projection of the positions q (springs: their direction now at the
/// length their curve asks; prisms: the six corners about their centroid,
/// moved along the volume gradient onto the rest volume by one Newton
/// step), and u any vector over the nodes, whose L u = sum w A^T A u comes
/// in the same pass (the damping and the prescribed nodes, see
/// projective_dynamics.cpp).
void add_projections(const ProjectiveSystem& system, const NodeVectors& q, const NodeVectors& u, NodeSum4* out);

/// The same for a batch of W = #systems faces (2, 4, 8 or 16; a padding
/// lane repeats a real face), each a lane of node-major arrays laid out as
/// the solve's rows are: value [(node * 3 + axis) * W + face], for q, u and
/// out alike. Each face's lane gets the bits add_projections gives that
/// face alone.
void add_projections_across(std::span<const ProjectiveSystem* const> systems, const float* q, const float* u, float* out);

}  // namespace fw::physics::detail
