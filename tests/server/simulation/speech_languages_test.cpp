#include "speech_languages.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace fw::server {
namespace {

TEST(SpeechLanguages, ListsWhatAHelloMayChoose) {
  const auto languages = speech_languages();
  ASSERT_FALSE(languages.empty());
  EXPECT_TRUE(std::is_sorted(languages.begin(), languages.end(),
                             [](const auto& a, const auto& b) { return a.code < b.code; }));
  EXPECT_TRUE(std::any_of(languages.begin(), languages.end(), [](const auto& l) { return l.code == "en"; }));
  for (const auto& language : languages) {
    std::string refusal;
    EXPECT_EQ(chosen_language(language.code, refusal), language.code);
    EXPECT_EQ(refusal, "");
  }
}

TEST(SpeechLanguages, EmptyMeansTheDefaultAndAnUnknownOneIsRefusedSayingWhereTheListIs) {
  std::string refusal;
  EXPECT_EQ(chosen_language("", refusal), "en");
  EXPECT_EQ(chosen_language("de", refusal), "de");
  EXPECT_EQ(refusal, "");
  EXPECT_EQ(chosen_language("xx", refusal), "");
  EXPECT_EQ(refusal, "unknown language 'xx'; GET /api/languages lists the ones this server speaks");
  refusal.clear();
  EXPECT_EQ(chosen_language("DE", refusal), "") << "a hello's language is lower case";
  EXPECT_NE(refusal, "");
}

}  // namespace
}  // namespace fw::server
