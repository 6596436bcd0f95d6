#pragma once
// espeak-ng for the rest of avatar/speech: started once per process, and
// entered by one thread at a time. espeak-ng keeps its voice, its synthesis
// callback and its buffers in globals and is not thread-safe, so every call
// into it, from any part, must go through here.
// Thread-safe: one process-wide mutex serialises every synthesis.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace fw::speech {

/// What espeak-ng reported while synthesising one text.
struct SynthesisEvents {
  struct Phoneme {
    std::string name;  ///< espeak-ng's ASCII mnemonic ("aI", "tS", "_:")
    int start_ms = 0;  ///< from the start of the audio
  };
  struct Word {
    std::size_t code_point = 0;  ///< where the word starts in the text, counted from 0
    int start_ms = 0;
  };
  std::vector<Phoneme> phonemes;
  std::vector<Word> words;
  std::vector<std::int16_t> samples;  ///< mono
  int sample_rate_hz = 0;
};

/// Synthesises `text` (UTF-8) in the voice for `language`, as espeak-ng
/// does at its default rate, and stops early once the audio is longer than
/// `stop_after_s` seconds (what follows would be cut anyway). False and
/// `error` if espeak-ng could not start (no voice data), the language is
/// not one an installed voice speaks (the message names it and those that
/// are), or synthesis failed. An empty `text` only checks the language.
bool espeak_synthesize(std::string_view text, std::string_view language, double stop_after_s,
                       SynthesisEvents& out, std::string& error);

/// The languages the installed voices speak (lower case), each with the
/// name of the voice that speaks it best: the voice whose own language it
/// is, else the one espeak-ng ranks first for it. Empty if espeak-ng could
/// not start.
std::map<std::string, std::string> espeak_languages();

}  // namespace fw::speech
