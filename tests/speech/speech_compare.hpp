#pragma once
// Whether two syntheses of one line agree. espeak-ng's output depends a
// little on what it said before (its wave generator keeps state such as the
// pitch flutter's phase from one synthesis to the next): the same line
// comes out with the same phonemes, but times may move by a few
// milliseconds and the samples differ. What a race between threads would
// break (another voice's phonemes, audio lost or doubled) shows far beyond
// these tolerances.
#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "fw/speech/phoneme_timing.hpp"

namespace fw::test {

/// Phonemes and times agree within the drift one synthesis leaves on the next.
inline constexpr double kSynthesisDriftS = 0.02;

inline testing::AssertionResult same_speech(const speech::PhonemeTiming& a, const speech::PhonemeTiming& b) {
  if (a.phonemes.size() != b.phonemes.size())
    return testing::AssertionFailure() << a.phonemes.size() << " phonemes against " << b.phonemes.size();
  for (std::size_t i = 0; i < a.phonemes.size(); ++i) {
    const auto& p = a.phonemes[i];
    const auto& q = b.phonemes[i];
    if (p.name != q.name || std::abs(p.start_s - q.start_s) > kSynthesisDriftS)
      return testing::AssertionFailure() << "phoneme " << i << ": " << p.name << " at " << p.start_s << " s against "
                                         << q.name << " at " << q.start_s << " s";
  }
  if (std::abs(a.length_s() - b.length_s()) > kSynthesisDriftS)
    return testing::AssertionFailure() << a.length_s() << " s of audio against " << b.length_s();
  if (a.truncated != b.truncated || a.spoken_bytes != b.spoken_bytes)
    return testing::AssertionFailure() << "cut differently";
  return testing::AssertionSuccess();
}

}  // namespace fw::test
