#include "speech_languages.hpp"

#include "fw/codec/messages.hpp"
#include "fw/speech/languages.hpp"

namespace fw::server {

std::vector<SpeechLanguage> speech_languages() {
  std::vector<SpeechLanguage> list;
  for (speech::Language& language : speech::installed_languages())
    // The hello carries a language of this shape only (PROTOCOL.md 5.1):
    // a voice named otherwise could never be chosen, so it is not listed.
    if (codec::is_language_code(language.code)) list.push_back({std::move(language.code), std::move(language.name)});
  return list;
}

std::string chosen_language(std::string_view requested, std::string& refusal) {
  if (requested.empty()) return std::string(kDefaultSpeechLanguage);
  if (codec::is_language_code(requested) && speech::speaks_language(requested)) return std::string(requested);
  refusal = "unknown language '" + std::string(requested.substr(0, codec::kMaxLanguageBytes)) +
            "'; GET /api/languages lists the ones this server speaks";
  return {};
}

}  // namespace fw::server
