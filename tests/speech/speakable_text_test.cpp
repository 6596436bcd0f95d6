#include "fw/speech/speakable_text.hpp"

#include <gtest/gtest.h>

namespace fw::speech {
namespace {

TEST(SpeakableText, WordsStayAndKeepTheirBytes) {
  EXPECT_EQ(speakable_text("Hello, world!"), "Hello, world!");
  EXPECT_EQ(speakable_text("Grüße, 3 Äpfel"), "Grüße, 3 Äpfel");
  EXPECT_TRUE(has_speech("Grüße"));
  EXPECT_TRUE(has_speech("42"));
}

TEST(SpeakableText, EmojiAndWordlessPunctuationBecomeSpaces) {
  // U+1F600 is four bytes: four spaces, so offsets into the line still hold.
  EXPECT_EQ(speakable_text("hi \xF0\x9F\x98\x80 you"), "hi      you");
  EXPECT_EQ(speakable_text("ok :-) !!! ^_^"), "ok            ");
  EXPECT_EQ(speakable_text("<3 u"), "<3 u");  // a digit makes it a word: "less than three"
  // A family: emoji joined by U+200D, each with U+FE0F.
  const std::string family = "\xF0\x9F\x91\xA8\xE2\x80\x8D\xF0\x9F\x91\xA9\xEF\xB8\x8F";
  EXPECT_EQ(speakable_text(family), std::string(family.size(), ' '));
  EXPECT_FALSE(has_speech(speakable_text(family + " :) \xF0\x9F\x91\x8D\xF0\x9F\x8F\xBD")));
  // An emoji inside a word leaves the word; what it parted from the word
  // goes if it is no word itself.
  EXPECT_EQ(speakable_text("cool\xF0\x9F\x98\x8E!"), "cool     ");
  EXPECT_EQ(speakable_text("a\xF0\x9F\x98\x8E" "b"), "a    b");
}

TEST(SpeakableText, InvalidBytesAndControlsBecomeSpaces) {
  EXPECT_EQ(speakable_text("a\xFF" "b\tc\n"), "a b c ");
  EXPECT_EQ(speakable_text("\xC3"), " ");  // a truncated two-byte sequence
  EXPECT_FALSE(has_speech(""));
  EXPECT_FALSE(has_speech("   "));
}

TEST(SpeakableText, CodePointsCountToByteOffsets) {
  const std::string text = "Grüße dich";  // ü and ß are two bytes each
  EXPECT_EQ(byte_offset_of_code_point(text, 0), 0u);
  EXPECT_EQ(byte_offset_of_code_point(text, 6), 8u);  // "dich"
  EXPECT_EQ(byte_offset_of_code_point(text, 100), text.size());
}

}  // namespace
}  // namespace fw::speech
