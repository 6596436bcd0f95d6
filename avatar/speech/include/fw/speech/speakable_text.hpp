#pragma once
// What of a chat line is read aloud. espeak-ng reads whatever it is given:
// "😀" becomes "grinning face" and ":-)" "colon", which a face mouthing a
// chat line must not do (an emoticon is appraised as an expression instead,
// avatar/behavior's chat_appraisal). So emoji are blanked, and so is every
// word (a run between spaces) without a letter or a digit. Blanking replaces
// each byte by a space: a byte offset into the result is the same offset
// into the line, which is how a cut line reports how much of it was spoken.
#include <string>
#include <string_view>

namespace fw::speech {

/// `text` (UTF-8, possibly invalid) with emoji, emoji modifiers and joiners,
/// invalid bytes and control characters, and words without a letter or a
/// digit (once the emoji are gone), each byte replaced by a space. Always
/// `text.size()` bytes long, and its own speakable text.
std::string speakable_text(std::string_view text);

/// Whether `text` has anything to say: a letter or a digit.
bool has_speech(std::string_view text);

/// The byte offset in `utf8` (valid UTF-8) of the code point numbered
/// `code_points` from 0; `utf8.size()` past the end. espeak-ng counts its
/// text positions in code points.
std::size_t byte_offset_of_code_point(std::string_view utf8, std::size_t code_points);

}  // namespace fw::speech
