#pragma once
// The jaw and lip channels that speech moves (a lip-sync track's visemes:
// avatar/speech), and how a speaking face's expression gives them up: while
// a line is said the track decides those channels and the expression keeps
// the rest of the face (a smile's cheeks and lip corners stay).
#include <array>

#include "fw/codec/face_params.hpp"

namespace fw::behavior {

using AuTargets = std::array<float, codec::kAuChannelCount>;

/// Upper-lip raiser, chin raiser, lip stretcher, lip tightener, lip pressor,
/// lips part, jaw drop, mouth stretch.
inline constexpr std::array<int, 8> kArticulationAus = {10, 17, 20, 23, 24, 25, 26, 27};

/// `au` with its articulation channels taken from `mouth`.
void articulate(AuTargets& au, const AuTargets& mouth);

/// `au` with its articulation channels at rest: what a physics face's
/// tissue is given while a track owns the mouth. Speech moves the jaw and
/// lips at syllable rate, which the tissue follows at about half and late
/// (avatar/physics README, "Physics against kinematic"), so the frames show
/// the track's mouth; a tissue that spoke too would measure a residual of
/// its own mouth, which its corrective weights would then lay on the
/// track's (0.17 mm RMS over the face, 1.6 mm at worst).
AuTargets without_articulation(AuTargets au);

}  // namespace fw::behavior
