#pragma once
// The generic face fitted to one person: the skin's x and y moved to where
// the package's fit puts them, depth kept from the generic face, UVs taken
// from the fitted positions (the face texture is aligned to the model frame),
// the eye and mouth layers moved with the features they sit behind, and the
// head shell stretched to the person's outline.
#include <span>

#include <glm/vec2.hpp>

#include "fw/model/generic_face.hpp"

namespace fw::model {

/// @param[in] generic  the generic face
/// @param[in] fitted_xy  #V of generic.skin: where each vertex lies on this face
/// @param[in] head_outline  the person's silhouette on the head's rays, or
///                          empty for the generic head (see head_shell.hpp)
/// @return the fitted face; same topology, regions, anchors and holes
GenericFace fit_generic_face(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                             std::span<const float> head_outline = {});

}  // namespace fw::model
