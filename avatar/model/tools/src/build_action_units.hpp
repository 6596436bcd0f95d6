#pragma once
#include <array>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::facegen {

/// The action-unit basis of `face` (skin, regions and landmarks set): for
/// each FaceParams channel, the handles' displacements spread over the
/// allowed regions with a smooth falloff ((1 - (d/r)^2)^2, blended where
/// handles overlap), plus the jaw rotation of AU 26/27; then split between
/// mesh motion and texture slide by the unit's mesh share.
std::array<model::Morph, codec::kAuChannelCount> build_action_units(const model::GenericFace& face);

}  // namespace fw::facegen
