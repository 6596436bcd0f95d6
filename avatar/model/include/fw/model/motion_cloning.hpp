#pragma once
// Facial motion cloning: carrying the generic face's morphs (per-vertex
// displacements) over to a fitted face. Deterministic and computed from the
// package's fit alone, so the server and every client derive the same
// morphs for the same avatar.
//
// Each vertex's displacement is mapped by the local linear part of the fit
// at that vertex (a 2x2 Jacobian estimated by least squares over the edges
// to its neighbours): a face with a wider mouth gets a proportionally wider
// smile, a longer face a longer jaw drop. Depth is scaled by the square root
// of the Jacobian's determinant (the local scale), since the fit keeps the
// template's depth profile.
#include <span>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/model/mesh.hpp"
#include "fw/model/morph.hpp"

namespace fw::model {

/// The fit's local linear map at each vertex.
/// @param[in] generic_skin  the generic face's skin (positions and triangles)
/// @param[in] fitted_xy     #V fitted positions
/// @return #V Jacobians d(fitted)/d(generic); identity where a vertex has too
///         few neighbours to tell
std::vector<glm::mat2> fit_jacobians(const Mesh& generic_skin, std::span<const glm::vec2> fitted_xy);

/// The generic morph carried over to the fitted face.
Morph clone_morph(const Morph& generic, std::span<const glm::mat2> jacobians);

}  // namespace fw::model
