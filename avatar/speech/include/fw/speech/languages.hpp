#pragma once
// The languages this machine's espeak-ng can say a line in, for a server
// that lets each person choose theirs (and lists them to clients) and for
// anyone who must check a language before asking for a line in it.
// Thread-safe: the list is read from espeak-ng once per process, under the
// engine's mutex (src/espeak_engine.hpp).
#include <string>
#include <string_view>
#include <vector>

namespace fw::speech {

struct Language {
  std::string code;  ///< an espeak-ng language, lower case: "en", "en-us", "de", "pt-br"
  std::string name;  ///< the name of the voice that speaks it: "English (America)"
};

/// One entry per language code an installed voice speaks, sorted by code;
/// empty when espeak-ng cannot start (no voice data).
std::vector<Language> installed_languages();

/// Whether an installed voice speaks `code` (compared as espeak-ng does,
/// without regard to case).
bool speaks_language(std::string_view code);

}  // namespace fw::speech
