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
// (the paper has one per articulator parameter). Strongly dominant
// segments resist their neighbours: the bilabials and labiodentals, whose
// lips must really close or touch the teeth, have alpha 6-8 against the
// vowels' 1, so at their centre they reach about 90 % of their target
// between two open vowels; the tongue consonants (t, k, n, s) leave the
// lips to the vowels around them (alpha 0.5-0.8), as the paper's lip
// rounding anticipated across consonants does; h (alpha 0.15) shows the
// vowel it precedes. The rates (10-45 per second: a dominance halves in
// 15-70 ms) are ours, chosen so that a syllable's vowel opens the mouth
// and its consonants close it at ordinary speech rates; the paper fits them
// per speaker and segment.
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
