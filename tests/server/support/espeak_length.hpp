#pragma once
// espeak-ng's own length of a line, as avatar/speech makes its lip-sync
// track: what the tests of a line said in a language compare the server's
// figures with (the simulation's event, the speaking message).
#include <string>

#include <gtest/gtest.h>

#include "fw/speech/phoneme_timing.hpp"
#include "fw/speech/speech_track.hpp"

namespace fw::test {

/// A line whose length differs much between German and English: numbers
/// are said as words of each language, and German says these ones longer
/// (about 4.7 s against 3.6 s).
inline constexpr const char* kLineLongerInGerman = "Im Jahr 1999 waren es 48 Leute";

/// The track's length of `text` said in `language`, in milliseconds.
inline double espeak_track_ms(const std::string& text, const std::string& language) {
  speech::PhonemeTiming timing;
  std::string error;
  EXPECT_TRUE(speech::time_phonemes(text, language, speech::SpeechLimits{}, timing, error)) << error;
  return speech::speech_track(timing).length_s() * 1000.0;
}

}  // namespace fw::test
