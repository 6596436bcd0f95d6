#pragma once
// Where espeak-ng reads its voice data (phoneme tables, dictionaries, voice
// files): the server serves this very folder to the browser's read aloud
// (web/speech), so that the browser's synthesiser speaks from the data the
// lips were timed with.
// Thread-safe: goes through the process-wide espeak-ng lock.
#include <string>

namespace fw::speech {

/// The espeak-ng-data folder espeak-ng uses in this process (starting
/// espeak-ng if it has not started yet); empty if espeak-ng could not start.
std::string espeak_data_folder();

}  // namespace fw::speech
