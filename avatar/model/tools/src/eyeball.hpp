#pragma once
// The eyeballs behind the eye holes: an anatomical globe with a corneal bulge
// and a widening past its equator that keeps the corners of the hole filled.
#include "fw/model/generic_face.hpp"

namespace fw::facegen {

/// The globe's radius: 12 mm, an adult eye, in model units.
inline constexpr float kEyeballRadius = 12.0f / model::kMillimetresPerUnit;

/// Distance of the eyeball's surface from its centre at `angle` from the
/// front pole (radians): the globe, the cornea in front of it and the
/// widening toward the equator.
float eyeball_profile(float angle);

/// The eyeball behind each eye hole of `face` (its skin must be built):
/// centred on the hole, as far forward as the lids let it sit.
void build_eyes(model::GenericFace& face);

}  // namespace fw::facegen
