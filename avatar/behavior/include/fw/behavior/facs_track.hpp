#pragma once
// A FACS expression sentence (face scripts: ClearAllFrame BeginKeyFrame ...
// Animate N ... end) as a timed track of action-unit targets a person's
// command plays on their avatar.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/model/expressions.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::behavior {

using AuTargets = std::array<float, codec::kAuChannelCount>;

struct AuTrack {
  /// A script step (Animate N / Hold N count steps) lasts this long.
  static constexpr double kStepS = 0.1;
  /// The last pose is held this long, then released over kReleaseS.
  static constexpr double kHoldS = 1.5, kReleaseS = 0.5;

  std::vector<double> times_s;   ///< key times, increasing, from 0
  std::vector<AuTargets> poses;  ///< pose at each key

  double length_s() const { return times_s.empty() ? 0 : times_s.back(); }
  /// Targets `t_s` into the track (linear between keys).
  AuTargets at(double t_s) const;
};

/// The track of expression sentence `animation` on a face whose action-unit
/// targets are `current` when it starts. ClearAllFrame starts from the
/// neutral face, each keyframe a full pose (unlisted AUs at 0), and releases
/// to neutral; KeepAllFrame starts from `current`, each keyframe sets the AUs
/// it lists and keeps the others as they were, and releases back to
/// `current`. A written intensity x weighs x / 2 (script::AuIntensity).
AuTrack animation_track(const script::KeyframeAnimation& animation, const AuTargets& current);

/// The track of the first expression sentence in `sentence`, on a face at
/// `current` (as animation_track); false and `error` (the script's first
/// error with its line and column, or "no expression sentence") if none.
bool facs_track(std::string_view sentence, const AuTargets& current, AuTrack& track, std::string& error);
/// The same on a neutral face.
bool facs_track(std::string_view sentence, AuTrack& track, std::string& error);

/// A track that eases into one of avatar/model's expressions (cunning,
/// teasing: those the emotion model has no primary for) at `intensity`,
/// holds it for `seconds` and eases out.
AuTrack expression_track(model::Expression expression, float intensity, double seconds);

}  // namespace fw::behavior
