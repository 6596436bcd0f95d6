#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "face_points.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::facegen {

/// The region of a skin triangle, from its centroid: rules in priority order
/// (rim, lips, mouth corners, lids, brows, nose, forehead, chin, jaw, cheeks),
/// so every triangle gets exactly one.
model::FaceRegion region_of(glm::vec2 centroid, const FacePoints& face);

}  // namespace fw::facegen
