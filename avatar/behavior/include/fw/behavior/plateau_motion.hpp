#pragma once
// The small, slow wavering of an expression that is held. A real face never
// holds a smile or a frown perfectly still; an animated one that does looks
// frozen the moment its expression reaches its plateau. Perlin ("Layered
// compositing of facial expression", SIGGRAPH 1997 technical sketch) keeps
// faces alive by adding band-limited noise to every expression parameter;
// here each active action-unit channel wavers by a few percent of its own
// strength, each with its own noise sequence.
//
// It is applied to what the face shows, after the physics face: the tissue
// may rest (and cost nothing) while the expression on it still lives.
#include <array>
#include <cstdint>

#include "fw/codec/face_params.hpp"

namespace fw::behavior {

/// Relative amplitude: a channel at 0.6 wavers by about +-0.03 (5 %), a few
/// of the codec's 1/256 steps, visible on a plateau but no new expression.
inline constexpr float kPlateauMotionShare = 0.05f;
/// Wavering rate: the slow end of facial motion, about 0.4 cycles a second.
inline constexpr float kPlateauMotionHz = 0.4f;
/// Channels weaker than this are left alone: a face at rest stays at rest
/// (its head, eyes and blinks keep it alive).
inline constexpr float kPlateauMotionFrom = 0.05f;

/// `au` wavered at time `t_s` (seconds) for the face whose noise is `seed`.
void add_plateau_motion(std::array<float, codec::kAuChannelCount>& au, double t_s, std::uint32_t seed);

}  // namespace fw::behavior
