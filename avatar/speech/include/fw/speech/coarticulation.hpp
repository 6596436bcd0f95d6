#pragma once
// Coarticulation: the mouth never stops at one phoneme's shape before going
// on to the next; each segment pulls the articulators toward its target
// with a strength that rises toward its centre and fades on either side.
//
// Cohen and Massaro, "Modeling coarticulation in synthetic visual speech"
// (in Thalmann and Thalmann, eds., Models and Techniques in Computer
// Animation, Springer 1993, pp. 139-156): segment s has the dominance
//   D_s(t) = alpha_s * exp(-theta_s * |t - c_s|^c)
// around its centre c_s, with one rate theta before the centre
// (anticipation) and another after it (carry-over), and the face shows the
// dominance-weighted mean of the targets:
//   F(t) = sum_s D_s(t) T_s / sum_s D_s(t).
// We use c = 1 and one dominance per segment for all the lip and jaw units
// (the paper has one per articulator parameter). The constants are ours
// (src/coarticulation.cpp; the paper fits them per speaker and segment),
// chosen on espeak-ng's speech so that each syllable's vowel opens the
// mouth and its consonants close it again:
// - bilabials and labiodentals, whose lips must really close or touch the
//   teeth, are strongly dominant (alpha 8 and 6 against the vowels' 1), so
//   between two open vowels they reach about 90 % of their target at their
//   centre; their dominance falls fast (rates 50 before, 80 per second after:
//   the lips part quickly at the release);
// - the other consonants weigh about as much as the vowels (alpha 1-1.5,
//   rate 30 per second), so the jaw rises for them while they take on
//   part of the neighbouring vowels' rounding; h (alpha 0.3) shows the vowel it precedes;
// - vowels spread further (rates 25 and 30 per second: a dominance halves
//   in about 25 ms), and a pause (alpha 1.5, rate 15) brings the mouth to rest.
#include <span>

#include "fw/speech/au_targets.hpp"
#include "fw/speech/visemes.hpp"

namespace fw::speech {

/// A stretch of time during which one viseme is the target.
struct VisemeSegment {
  Viseme viseme = Viseme::rest;
  double start_s = 0;
  double end_s = 0;
  double centre_s() const { return 0.5 * (start_s + end_s); }
};

struct Dominance {
  float magnitude = 1;          ///< alpha
  float anticipation_per_s = 1; ///< theta before the segment's centre
  float carryover_per_s = 1;    ///< theta after it
};

/// The dominance function's constants for `viseme`.
Dominance dominance_of(Viseme viseme);

/// The dominance of `segment` at `t_s`.
float dominance_at(const VisemeSegment& segment, double t_s);

/// The blended targets at `t_s` of `segments` (in time order, not
/// overlapping). Segments whose dominance has fallen below a millionth
/// are skipped; all zeros if there are none.
AuTargets coarticulate(std::span<const VisemeSegment> segments, double t_s);

}  // namespace fw::speech
