#pragma once
// Physics-synthesised action units (the PBD face paper's use of its muscle
// model: blend shapes made by simulation). For each AU channel the reference
// face is simulated with that channel alone at intensity 1 until it comes to
// rest; the skin's displacement is the channel's vertex morph. It replaces
// the geometric vertex fields of the face's basis; the texture slides stay.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::physics {

class FacePool;

struct BasisSynthesisOptions {
  double frame_s = 1.0 / 30.0;  ///< step length while settling
  double max_seconds = 6.0;     ///< give up waiting for rest after this long
  /// Displacements shorter than this (model units; 1e-3 = 0.06 mm) are
  /// written as zero, so the asset lists only what a unit really moves.
  float zero_below = 1e-3f;
};

/// The settled skin displacement of every AU channel of `face`, simulated
/// with the solver rooms step (projective dynamics), so that a room's face
/// holding one unit measures as that unit, and no individual variation.
/// @param[in] face  a sound face
/// @param[in] pool  threads to spread the channels over (null: this thread)
/// @return per channel, #V displacements in model units
std::array<std::vector<glm::vec3>, codec::kAuChannelCount> synthesize_action_units(
    const model::GenericFace& face, const BasisSynthesisOptions& options = {}, FacePool* pool = nullptr);

/// `face` with its action units' vertex fields replaced by `displacements`,
/// and without corrective components (they were fitted against the old ones).
void replace_action_unit_displacements(
    model::GenericFace& face, const std::array<std::vector<glm::vec3>, codec::kAuChannelCount>& displacements);

}  // namespace fw::physics
