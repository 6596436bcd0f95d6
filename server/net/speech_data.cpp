#include "speech_data.hpp"

#include <algorithm>
#include <array>
#include <system_error>

#include "fw/speech/espeak_data_folder.hpp"

namespace fw::server {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 4> kPhonemeTables = {"phontab", "phonindex", "phondata", "intonations"};
// espeak-ng's voice names are at most 16 bytes on the wire (hello's language).
constexpr std::size_t kMaxCodeBytes = 16;
constexpr std::size_t kMaxDictLanguageBytes = 8;

bool is_lower_or_digit(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); }

bool is_voice_code(std::string_view code) {
  if (code.empty() || code.size() > kMaxCodeBytes || code.front() == '-') return false;
  for (char c : code)
    if (!is_lower_or_digit(c) && c != '-') return false;
  return true;
}

bool is_dictionary(std::string_view name) {
  constexpr std::string_view kSuffix = "_dict";
  if (!name.ends_with(kSuffix)) return false;
  const std::string_view language = name.substr(0, name.size() - kSuffix.size());
  if (language.size() < 2 || language.size() > kMaxDictLanguageBytes) return false;
  for (char c : language)
    if (c < 'a' || c > 'z') return false;
  return true;
}

bool is_plain_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

}  // namespace

SpeechData::SpeechData(const fs::path& folder, const std::map<std::string, std::string>& voice_files) {
  if (folder.empty()) return;
  for (std::string_view table : kPhonemeTables)
    if (is_plain_file(folder / table)) files_.emplace(std::string(table), folder / table);
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (is_dictionary(name) && is_plain_file(entry.path())) files_.emplace(name, entry.path());
  }
  // Voice files sit in family folders (lang/gmw/en-US), and a code may be
  // said by a voice of another name (en-gb by lang/gmw/en): espeak-ng's
  // own choice, checked to stay inside the folder.
  for (const auto& [code, relative] : voice_files) {
    const fs::path path(relative);
    const bool inside = !relative.empty() && path.is_relative() &&
                        std::none_of(path.begin(), path.end(), [](const fs::path& part) { return part == ".."; });
    if (is_voice_code(code) && inside && is_plain_file(folder / path)) files_.emplace("lang/" + code, folder / path);
  }
}

std::optional<fs::path> SpeechData::find(std::string_view name) const {
  const bool well_formed = std::find(kPhonemeTables.begin(), kPhonemeTables.end(), name) != kPhonemeTables.end() ||
                           is_dictionary(name) || (name.starts_with("lang/") && is_voice_code(name.substr(5)));
  if (!well_formed) return std::nullopt;
  const auto it = files_.find(name);
  if (it == files_.end()) return std::nullopt;
  return it->second;
}

std::string SpeechData::refusal(std::string_view name) {
  return "no speech data named '" + std::string(name.substr(0, 64)) +
         "'; /speech/data/ serves phontab, phonindex, phondata, intonations, LANG_dict and lang/CODE "
         "for the codes GET /api/languages lists";
}

const SpeechData& served_speech_data() {
  static const SpeechData data(fw::speech::espeak_data_folder(), fw::speech::espeak_voice_files());
  return data;
}

}  // namespace fw::server
