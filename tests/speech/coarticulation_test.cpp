#include "fw/speech/coarticulation.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace fw::speech {
namespace {

const auto kJaw = static_cast<std::size_t>(codec::au_channel(26, codec::AuSide::both));
const auto kPressor = static_cast<std::size_t>(codec::au_channel(24, codec::AuSide::both));

TEST(Coarticulation, OneSegmentShowsItsTarget) {
  const std::vector<VisemeSegment> one = {{Viseme::open_vowel, 0.0, 0.2}};
  EXPECT_EQ(coarticulate(one, 0.1), viseme_targets(Viseme::open_vowel));
  EXPECT_EQ(coarticulate(one, 0.5), viseme_targets(Viseme::open_vowel));  // the only one, however far
  EXPECT_EQ(coarticulate({}, 0.1), AuTargets{});
}

TEST(Coarticulation, DominanceFallsExponentiallyFromTheCentre) {
  const VisemeSegment s{Viseme::bilabial, 0.0, 0.1};
  const Dominance d = dominance_of(Viseme::bilabial);
  EXPECT_FLOAT_EQ(dominance_at(s, 0.05), d.magnitude);
  EXPECT_NEAR(dominance_at(s, 0.0), d.magnitude * std::exp(-d.anticipation_per_s * 0.05), 1e-5);
  EXPECT_NEAR(dominance_at(s, 0.1), d.magnitude * std::exp(-d.carryover_per_s * 0.05), 1e-5);
}

TEST(Coarticulation, BilabialsCloseBetweenOpenVowels) {
  // "ama" at espeak-ng's pace: 120 ms vowels around a 70 ms m.
  const std::vector<VisemeSegment> ama = {
      {Viseme::open_vowel, 0.0, 0.12}, {Viseme::bilabial, 0.12, 0.19}, {Viseme::open_vowel, 0.19, 0.31}};
  const AuTargets closure = coarticulate(ama, 0.155);
  const AuTargets m = viseme_targets(Viseme::bilabial);
  EXPECT_GT(closure[kPressor], 0.85f * m[kPressor]);
  EXPECT_LT(closure[kJaw], 0.1f * viseme_targets(Viseme::open_vowel)[kJaw]);
  // ... while a tongue consonant, no stronger than the vowels, is pulled
  // open by them.
  const std::vector<VisemeSegment> ata = {
      {Viseme::open_vowel, 0.0, 0.12}, {Viseme::alveolar, 0.12, 0.19}, {Viseme::open_vowel, 0.19, 0.31}};
  EXPECT_GT(coarticulate(ata, 0.155)[kJaw], viseme_targets(Viseme::alveolar)[kJaw] + 0.03f);
  EXPECT_GT(coarticulate(ata, 0.155)[kJaw], 2 * closure[kJaw]);
  // The vowels still open: their centres are mostly their own.
  EXPECT_GT(coarticulate(ama, 0.06)[kJaw], 0.7f * viseme_targets(Viseme::open_vowel)[kJaw]);
}

TEST(Coarticulation, RoundingStartsBeforeTheVowel) {
  // "s u": the lips are rounding by the end of the s (anticipation).
  const std::vector<VisemeSegment> su = {
      {Viseme::rest, -0.3, 0.0}, {Viseme::alveolar, 0.0, 0.1}, {Viseme::close_rounded_vowel, 0.1, 0.25}};
  const auto tightener = static_cast<std::size_t>(codec::au_channel(23, codec::AuSide::both));
  const float rounded = viseme_targets(Viseme::close_rounded_vowel)[tightener];
  EXPECT_GT(coarticulate(su, 0.1)[tightener], 0.3f * rounded);
  EXPECT_LT(coarticulate(su, 0.02)[tightener], coarticulate(su, 0.08)[tightener]);
}

}  // namespace
}  // namespace fw::speech
