#pragma once
// The voice data of the server's espeak-ng, served read-only to the
// browser's read aloud (web/speech) at /speech/data/NAME, so the browser's
// synthesiser speaks a line from the very data the speaker's lips were
// timed with. Only names of a fixed shape are answered, each looked up in a
// table made once from the folder, so a request can never name a path
// outside it ("../", absolute paths, links elsewhere are never opened):
//   phontab, phonindex, phondata, intonations   the phoneme tables
//   LANG_dict                                   a language's dictionary (2 to 8 letters)
//   lang/CODE                                   the voice file espeak-ng says language CODE ("en",
//                                               "pt-br") with, wherever it is below lang/
// Thread-safe: immutable once made.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace fw::server {

class SpeechData {
 public:
  /// Indexes `folder` (an espeak-ng-data folder) and the voice file of
  /// each language code (`voice_files`: code -> path relative to `folder`,
  /// as fw::speech::espeak_voice_files gives them; one that climbs out of
  /// the folder or is absolute is left out). An empty or missing folder
  /// serves nothing.
  SpeechData(const std::filesystem::path& folder, const std::map<std::string, std::string>& voice_files);

  /// The file that `name` (the part of the path after /speech/data/) names,
  /// or nothing for a name of another shape or one the folder lacks.
  std::optional<std::filesystem::path> find(std::string_view name) const;

  /// Why `name` found nothing, for the 404's body: what was wrong, what to ask instead.
  static std::string refusal(std::string_view name);

 private:
  std::map<std::string, std::filesystem::path, std::less<>> files_;  ///< served name -> file
};

/// The data of this process's espeak-ng (fw::speech::espeak_data_folder
/// and espeak_voice_files), indexed on first use.
const SpeechData& served_speech_data();

}  // namespace fw::server
