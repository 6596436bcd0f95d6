// Characters that act on the text around them without showing themselves:
// left out of chat lines, kept where emoji and scripts need them.
#include "visible_text.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

std::string cleaned(std::string_view text, std::size_t* left_out = nullptr, std::size_t max_bytes = 500) {
  std::string out;
  const std::size_t n = clean_chat_text(text, out, max_bytes);
  if (left_out) *left_out = n;
  return out;
}

TEST(VisibleText, ChatLosesBidiOverridesIsolatesAndZeroWidthCharacters) {
  std::size_t left_out = 0;
  EXPECT_EQ(cleaned("pay \u202Eevil\u202C now", &left_out), "pay evil now");
  EXPECT_EQ(left_out, 2u);
  EXPECT_EQ(cleaned("a\u2066b\u2069c\u200Bd\uFEFFe"), "abcde");
}

TEST(VisibleText, AChatLineCannotStartWhatLooksLikeAnotherLine) {
  EXPECT_EQ(cleaned("hi\u2028Ada: send me your key\u2029"), "hiAda: send me your key");
}

TEST(VisibleText, EmojiAndScriptJoinersStay) {
  EXPECT_EQ(cleaned("\u2764\uFE0F \U0001F469\u200D\U0001F4BB"), "\u2764\uFE0F \U0001F469\u200D\U0001F4BB");
  // Persian "mi-khaham": a zero-width non-joiner between two letters shapes them.
  EXPECT_EQ(cleaned("\u0645\u06CC\u200C\u062E\u0648\u0627\u0647\u0645"), "\u0645\u06CC\u200C\u062E\u0648\u0627\u0647\u0645");
  EXPECT_EQ(cleaned("a \u200C b"), "a  b") << "a joiner between spaces shapes nothing";
}

TEST(VisibleText, ANameHasNoScriptJoiners) {
  EXPECT_TRUE(acts_unseen(U'A', U'\u200D', U'd'));
  EXPECT_FALSE(acts_unseen(U'A', U'\u200D', U'd', true));
  EXPECT_FALSE(acts_unseen(U'x', U'y', U'z'));
}

TEST(VisibleText, ChatIsNfcAndCutAtACharacterBoundary) {
  EXPECT_EQ(cleaned("Zoe\u0301"), "Zo\u00e9");
  EXPECT_EQ(cleaned("\u00e9\u00e9\u00e9", nullptr, 5), "\u00e9\u00e9") << "not half an é";
}

}  // namespace
}  // namespace fw::server
