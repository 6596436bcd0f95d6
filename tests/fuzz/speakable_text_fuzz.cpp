// Fuzzes what of a chat line is read aloud (avatar/speech's speakable_text,
// which every line meets before espeak-ng does). Whatever the bytes: the
// result has the line's length and is the line with some bytes replaced by
// spaces (so offsets into it are offsets into the line), it is valid UTF-8
// (espeak-ng never sees a broken sequence), it is its own speakable text
// (nothing left that a second pass would remove), it has something to say
// only if the line has a letter or a digit, and code-point offsets map to
// byte offsets that only grow. Seeded with lines of words, emoji and
// emoticons (corpus/speakable_text_fuzz).
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include <unicode/utf8.h>

#include "fw/speech/speakable_text.hpp"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

bool valid_utf8(std::string_view text) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  const auto length = static_cast<std::int32_t>(text.size());
  for (std::int32_t i = 0; i < length;) {
    UChar32 c = 0;
    U8_NEXT(bytes, i, length, c);
    if (c < 0) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const std::string speakable = fw::speech::speakable_text(line);
  check(speakable.size() == line.size());
  for (std::size_t i = 0; i < line.size(); ++i) check(speakable[i] == line[i] || speakable[i] == ' ');
  check(valid_utf8(speakable));
  check(fw::speech::speakable_text(speakable) == speakable);
  if (fw::speech::has_speech(speakable)) check(fw::speech::has_speech(line));
  std::size_t previous = 0;
  for (std::size_t n = 0; n <= speakable.size() + 1; ++n) {
    const std::size_t offset = fw::speech::byte_offset_of_code_point(speakable, n);
    check(offset >= previous && offset <= speakable.size());
    previous = offset;
  }
  return 0;
}
