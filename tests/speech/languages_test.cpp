#include "fw/speech/languages.hpp"

#include <algorithm>

#include <gtest/gtest.h>


namespace fw::speech {
namespace {

TEST(Languages, ListsEachInstalledLanguageOnceSortedByCode) {
  const std::vector<Language> languages = installed_languages();
  ASSERT_FALSE(languages.empty()) << "espeak-ng-data is installed (deploy/install-deps.sh)";
  EXPECT_TRUE(std::is_sorted(languages.begin(), languages.end(),
                             [](const Language& a, const Language& b) { return a.code < b.code; }));
  EXPECT_TRUE(std::adjacent_find(languages.begin(), languages.end(), [](const Language& a, const Language& b) {
                return a.code == b.code;
              }) == languages.end());
  for (const char* code : {"en", "en-us", "de", "fr", "es", "pt-br"}) {
    const auto it = std::find_if(languages.begin(), languages.end(), [&](const Language& l) { return l.code == code; });
    ASSERT_NE(it, languages.end()) << code;
    EXPECT_FALSE(it->name.empty()) << code;
  }
  for (const Language& language : languages) EXPECT_TRUE(speaks_language(language.code)) << language.code;
}

TEST(Languages, NamesComeFromTheVoiceWhoseLanguageItIs) {
  const std::vector<Language> languages = installed_languages();
  const auto name_of = [&](std::string_view code) {
    const auto it = std::find_if(languages.begin(), languages.end(), [&](const Language& l) { return l.code == code; });
    return it == languages.end() ? std::string() : it->name;
  };
  EXPECT_NE(name_of("de").find("German"), std::string::npos) << name_of("de");
  EXPECT_NE(name_of("en-us").find("English"), std::string::npos) << name_of("en-us");
  EXPECT_NE(name_of("fr").find("French"), std::string::npos) << name_of("fr");
}

TEST(Languages, UnknownLanguagesAreNotSpoken) {
  EXPECT_TRUE(speaks_language("DE")) << "compared as espeak-ng compares: without regard to case";
  EXPECT_FALSE(speaks_language("xx"));
  EXPECT_FALSE(speaks_language(""));
  EXPECT_FALSE(speaks_language("en us"));
}

}  // namespace
}  // namespace fw::speech
