#pragma once
// Which languages a person may choose for their chat lines to be said in:
// those this machine's espeak-ng speaks (avatar/speech). Checked when a
// hello names one (PROTOCOL.md 5.1), listed by GET /api/languages
// (PROTOCOL.md 8), here so that the parts above the simulation need not
// link espeak-ng themselves.
// Thread-safe: espeak-ng's list is read once per process.
#include <string>
#include <string_view>
#include <vector>

namespace fw::server {

/// The language of a person who chose none (a version-3 hello, or an empty
/// language) and of the room's own faces.
inline constexpr std::string_view kDefaultSpeechLanguage = "en";

struct SpeechLanguage {
  std::string code;  ///< "en", "en-us", "de", "pt-br", ...
  std::string name;  ///< "English (America)", ...
};

/// One entry per language an installed voice speaks, sorted by code.
std::vector<SpeechLanguage> speech_languages();

/// The language a hello's `requested` one means here: the default for an
/// empty one, else `requested` if a voice speaks it. Empty, with `refusal`
/// set to what to tell the person, when none does.
std::string chosen_language(std::string_view requested, std::string& refusal);

}  // namespace fw::server
