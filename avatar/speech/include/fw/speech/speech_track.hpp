#pragma once
// The lip-sync track of a spoken line: the jaw and lip action-unit targets
// that the writer's face plays while the line is heard, from the line's
// phoneme timing (phoneme_timing.hpp) through visemes (visemes.hpp) and
// coarticulation (coarticulation.hpp). The mouth is at rest (all zeros)
// before 0 and from the end on, so a face that plays it starts and ends
// with a still mouth.
// Thread-safe: a track is plain data; making one touches nothing shared.
#include <cstddef>
#include <vector>

#include "fw/speech/au_targets.hpp"
#include "fw/speech/coarticulation.hpp"
#include "fw/speech/phoneme_timing.hpp"

namespace fw::speech {

struct SpeechTrack {
  /// Keys are this far apart: espeak-ng's phonemes last 20 ms and more at
  /// its default rate, a lip closure 50-100 ms; 100 keys a second follow
  /// both, and a face drawn at up to 60 frames a second sees no steps.
  static constexpr double kKeyStepS = 0.01;
  /// The track goes on this long after the audio: the mouth closes after
  /// the last sound, as the lead lets it open before the first
  /// (PhonemeTiming::kLeadS).
  static constexpr double kCloseS = 0.15;

  std::vector<AuTargets> keys;  ///< at 0, kKeyStepS, ...; the first and last are all zeros
  bool truncated = false;       ///< the line was cut at SpeechLimits::max_seconds
  std::size_t spoken_bytes = 0; ///< how much of the line was spoken (PhonemeTiming::spoken_bytes)

  bool empty() const { return keys.empty(); }
  /// Seconds from the first key to the last; 0 for an empty track.
  double length_s() const;
  /// The targets `t_s` into the track, linear between keys; all zeros
  /// before 0 and after length_s().
  AuTargets at(double t_s) const;
};

/// The viseme segments of `phonemes`: one per phoneme, a diphthong split
/// in two halves (its glide), phonemes without a mouth shape left out.
std::vector<VisemeSegment> viseme_segments(std::span<const TimedPhoneme> phonemes);

/// The track of `timing`, kCloseS longer than its audio (empty if it has
/// no phonemes).
SpeechTrack speech_track(const PhonemeTiming& timing);

}  // namespace fw::speech
