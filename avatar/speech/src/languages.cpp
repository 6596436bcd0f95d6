#include "fw/speech/languages.hpp"

#include <algorithm>
#include <cctype>

#include "espeak_engine.hpp"

namespace fw::speech {

std::vector<Language> installed_languages() {
  std::vector<Language> list;
  for (auto& [code, name] : espeak_languages()) list.push_back({code, name});  // a std::map: sorted by code
  return list;
}

bool speaks_language(std::string_view code) {
  std::string lower(code);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return espeak_languages().contains(lower);
}

}  // namespace fw::speech
