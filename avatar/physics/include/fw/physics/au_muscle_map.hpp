#pragma once
// FACS action units to muscle activations: the muscle control level of the
// behavioral-animation paper (sec. 2, after Ekman & Friesen). The table is in
// au_muscle_map.cpp and README.md; a paired AU's left channel drives the left
// muscles, a midline AU both sides.
#include <array>
#include <span>

#include "fw/codec/face_params.hpp"
#include "fw/physics/facial_muscles.hpp"

namespace fw::physics {

struct AuMuscleTerm {
  std::string_view muscle;  ///< definition name (no side)
  float weight;             ///< activation per unit of AU intensity
};

/// The muscles FACS action unit `au` recruits (empty for an AU not carried).
std::span<const AuMuscleTerm> au_muscle_terms(int au);

/// Muscle activations for AU intensities (kAuChannels order): the weighted
/// sum of the channels that recruit each muscle, clamped to [0,1]. AU
/// intensities are clamped to [0,1] first; non-finite ones count as 0.
std::array<float, kMuscleCount> muscle_activations(const std::array<float, codec::kAuChannelCount>& au);

}  // namespace fw::physics
