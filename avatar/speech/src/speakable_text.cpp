#include "fw/speech/speakable_text.hpp"

#include <unicode/uchar.h>
#include <unicode/utf8.h>

namespace fw::speech {
namespace {

// Emoji and what only builds emoji (U+200D joiner, U+FE0F presentation
// selector, skin tones, regional indicators, keycap, tags). Below U+0080
// Emoji_Component also holds the digits, '#' and '*', which stay.
bool is_emoji(UChar32 c) {
  return c >= 0x80 && (u_hasBinaryProperty(c, UCHAR_EXTENDED_PICTOGRAPHIC) ||
                       u_hasBinaryProperty(c, UCHAR_EMOJI_COMPONENT));
}

void blank(std::string& text, std::size_t begin, std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) text[i] = ' ';
}

// Visits each code point of `text` (invalid bytes as c < 0) with its byte range.
template <class Visit>
void for_each_code_point(std::string_view text, Visit&& visit) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  const auto length = static_cast<std::int32_t>(text.size());
  std::int32_t i = 0;
  while (i < length) {
    const std::int32_t begin = i;
    UChar32 c = 0;
    U8_NEXT(bytes, i, length, c);
    visit(c, static_cast<std::size_t>(begin), static_cast<std::size_t>(i));
  }
}

}  // namespace

std::string speakable_text(std::string_view text) {
  std::string out(text);
  // What is never read, first: so that a second pass finds nothing more to
  // remove, a word is judged as espeak-ng would see it.
  for_each_code_point(text, [&](UChar32 c, std::size_t begin, std::size_t end) {
    if (c < 0 || u_iscntrl(c) || is_emoji(c)) blank(out, begin, end);
  });
  // Then words: runs of non-space code points; one without a letter or a
  // digit (":-)", "!!!", "^_^", the "!" an emoji parted from its word) is
  // punctuation espeak-ng would name aloud.
  std::size_t word_begin = 0;
  bool in_word = false, word_has_alnum = false;
  auto end_word = [&](std::size_t at) {
    if (in_word && !word_has_alnum) blank(out, word_begin, at);
    in_word = false;
  };
  const std::string blanked = out;
  for_each_code_point(blanked, [&](UChar32 c, std::size_t begin, std::size_t) {
    if (u_isUWhiteSpace(c)) {
      end_word(begin);
      return;
    }
    if (!in_word) {
      in_word = true;
      word_has_alnum = false;
      word_begin = begin;
    }
    if (u_isalnum(c)) word_has_alnum = true;
  });
  end_word(out.size());
  return out;
}

bool has_speech(std::string_view text) {
  bool any = false;
  for_each_code_point(text, [&](UChar32 c, std::size_t, std::size_t) { any = any || u_isalnum(c); });
  return any;
}

std::size_t byte_offset_of_code_point(std::string_view utf8, std::size_t code_points) {
  std::size_t i = 0;
  for (std::size_t n = 0; n < code_points && i < utf8.size(); ++n) {
    ++i;
    while (i < utf8.size() && (static_cast<std::uint8_t>(utf8[i]) & 0xC0) == 0x80) ++i;  // continuation bytes
  }
  return i;
}

}  // namespace fw::speech
