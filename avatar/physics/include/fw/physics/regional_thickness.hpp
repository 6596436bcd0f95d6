#pragma once
// How deep the soft tissue is, skin surface to bone, in each region of the
// face: the behavioural-animation paper's lattice (sec. 2) takes its depth
// from the face, and faces are thin over the forehead and nasal bones and
// thick over the cheeks, lips and chin.
#include "fw/model/generic_face.hpp"

namespace fw::physics {

/// Mean adult soft-tissue depth over `region`, millimetres (sources beside
/// the table in regional_thickness.cpp).
float regional_thickness_mm(model::FaceRegion region);

}  // namespace fw::physics
