// Display names: one spelling (NFC) per name, and nothing invisible that
// changes how the text around it shows.
#include "display_name.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

std::string normalized(const std::string& name) {
  std::string out;
  const std::string why = normalize_display_name(name, out);
  return why.empty() ? out : "refused: " + why;
}

TEST(DisplayName, IsNormalisedToNfc) {
  EXPECT_EQ(normalized("Zoe\u0301"), "Zo\u00e9") << "e + combining acute is é";
  EXPECT_EQ(normalized("Zo\u00e9"), "Zo\u00e9");
  EXPECT_EQ(normalized("Ada Lovelace"), "Ada Lovelace");
  EXPECT_EQ(normalized("\u674e\u534e"), "\u674e\u534e");
}

TEST(DisplayName, KeepsEmojiWithTheirJoinersAndSelectors) {
  EXPECT_EQ(normalized("Ada \U0001F469\u200D\U0001F4BB"), "Ada \U0001F469\u200D\U0001F4BB") << "woman technologist";
  EXPECT_EQ(normalized("Bo \u2764\uFE0F"), "Bo \u2764\uFE0F") << "red heart, emoji style";
}

TEST(DisplayName, RefusesBidiOverridesZeroWidthAndControls) {
  for (const std::string name : {"\u202Eevil", "Ada\u200B", "\u200B", "A\u2066B", "Ann\u200D", "x\u200Fy", "bell\a",
                                 "tab\there", "\uFEFFBo", "\u2028line", "\uE000private"}) {
    std::string out;
    const std::string why = normalize_display_name(name, out);
    EXPECT_NE(why.find("invisible or control character"), std::string::npos) << name << ": " << why;
  }
}

TEST(DisplayName, NeedsSomethingVisible) {
  std::string out;
  EXPECT_NE(normalize_display_name("   ", out).find("visible"), std::string::npos);
  EXPECT_NE(normalize_display_name("", out), "");
}

}  // namespace
}  // namespace fw::server
