#pragma once
// Where espeak-ng reads its voice data (phoneme tables, dictionaries, voice
// files): the server serves this very folder to the browser's read aloud
// (web/speech), so that the browser's synthesiser speaks from the data the
// lips were timed with.
// Thread-safe: goes through the process-wide espeak-ng lock.
#include <map>
#include <string>

namespace fw::speech {

/// The espeak-ng-data folder espeak-ng uses in this process (starting
/// espeak-ng if it has not started yet); empty if espeak-ng could not start.
std::string espeak_data_folder();

/// For each language an installed voice speaks (lower case, "en-gb"), the
/// file of the voice espeak-ng says it with, relative to the data folder
/// ("lang/gmw/en"); empty if espeak-ng could not start.
std::map<std::string, std::string> espeak_voice_files();

}  // namespace fw::speech
