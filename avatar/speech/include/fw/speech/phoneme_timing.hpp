#pragma once
// A line of text as espeak-ng speaks it: its phonemes with their start and
// end times, and the audio itself (for tests of the lip-sync against it, and
// later for a browser that reads lines aloud). The timing is espeak-ng's own
// (its phoneme events), at its default rate for the voice (175 words a
// minute), so mouth and voice agree by construction.
//
// Limits: at most kMaxTextBytes of text (a chat line, codec::kMaxChatBytes);
// at most max_seconds of speech (after the lead): a longer line is cut
// where the last word that starts in time begins, and says how much of the
// text was spoken.
// espeak-ng's output depends slightly on what it said before (its wave
// generator keeps state between syntheses): a line said again has the same
// phonemes, their times within a few milliseconds, and other samples.
// Thread-safe: any thread may call; espeak-ng runs one synthesis at a time
// (src/espeak_engine.hpp), so concurrent calls wait for each other.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::speech {

struct SpeechLimits {
  /// Longer text is refused: a chat line is never longer.
  static constexpr std::size_t kMaxTextBytes = codec::kMaxChatBytes;
  /// Speech beyond this is cut. 15 s is about 40 words at espeak-ng's 175
  /// words a minute: a long chat line, not a speech that holds a face.
  double max_seconds = 15.0;
};

struct TimedPhoneme {
  std::string name;    ///< espeak-ng's ASCII mnemonic ("p", "aI", "tS"; pauses start with '_')
  double start_s = 0;  ///< from the start of the audio
  double end_s = 0;    ///< the next phoneme's start, or the end of the audio
};

struct PhonemeTiming {
  /// Silence before the first sound (a "_" pause, to the sample): time for
  /// a face to open its mouth before the voice starts, as speakers do.
  static constexpr double kLeadS = 0.15;

  std::vector<TimedPhoneme> phonemes;  ///< in time order, pauses included; empty if nothing is said
  std::vector<std::int16_t> samples;   ///< the synthesised speech, mono
  int sample_rate_hz = 0;              ///< of `samples` (espeak-ng's 22050)
  bool truncated = false;              ///< the speech was cut at SpeechLimits::max_seconds
  /// How many bytes of the text were spoken: all of it unless truncated,
  /// else up to the first word that was cut off.
  std::size_t spoken_bytes = 0;

  /// The audio's length: kLeadS, then the speech; 0 if nothing is said.
  double length_s() const {
    return sample_rate_hz > 0 ? static_cast<double>(samples.size()) / sample_rate_hz : 0.0;
  }
};

/// The phonemes of `text` (UTF-8, at most SpeechLimits::kMaxTextBytes bytes)
/// spoken in `language` (an espeak-ng language such as "en", "en-us",
/// "de", "fr", "es"). Emoji and wordless punctuation are not spoken
/// (speakable_text.hpp); text with nothing left to say gives an empty
/// timing. False and `error` (what was wrong, what would be accepted) for
/// text that is too long, a language no installed voice speaks, or
/// espeak-ng failing.
bool time_phonemes(std::string_view text, std::string_view language, const SpeechLimits& limits,
                   PhonemeTiming& out, std::string& error);

}  // namespace fw::speech
