#pragma once
// The generator of the generic face asset. Deterministic: the same code gives
// the same face, which the test suite compares with the committed asset.
#include "fw/model/generic_face.hpp"

namespace fw::facegen {

/// Builds the generic face from the landmark template and the depth profile:
/// landmarks, rings around the eyes, brows and mouth, a hexagonal fill and a
/// rim that curves back to the ears, triangulated by a constrained Delaunay
/// triangulation with the eye contours, the lips and the face outline as
/// constraints; eye holes and the mouth slit cut out; regions assigned; then
/// the eyeball and mouth-cavity layers.
model::GenericFace generate_generic_face();

}  // namespace fw::facegen
