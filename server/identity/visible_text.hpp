#pragma once
// Which characters show themselves. Controls, bidi embeddings, overrides and
// isolates, zero-width characters and line separators change how the text
// around them reads without a glyph of their own: "\u202Eevil" shows
// reversed, "Ada\u200B" passes for Ada, and a line separator in a chat line
// starts what looks like another person's line. Display names with them
// are refused (display_name.hpp); chat lines lose them (clean_chat_text).
#include <cstddef>
#include <string>
#include <string_view>

namespace fw::server {

/// Whether `c` acts on the text around it without showing itself, given
/// its neighbours (0 at an end). Emoji keep the two invisible characters
/// they are written with: a variation selector after a visible character,
/// and a zero-width joiner between two pictographs. With
/// `script_joiners`, the zero-width joiner and non-joiner between two
/// letters stay too: they shape Persian and the Indic scripts. Names go
/// without (in a name, "A\u200Dda" would pass for Ada).
bool acts_unseen(char32_t before, char32_t c, char32_t after, bool script_joiners = false);

/// `text` (UTF-8) in NFC into `cleaned`, without the characters that act
/// unseen (script joiners kept), cut to at most `max_bytes` at a character's
/// boundary (NFC may lengthen a text); returns how many characters were left
/// out as unseen. Text that is not UTF-8 gives an empty `cleaned`.
std::size_t clean_chat_text(std::string_view text, std::string& cleaned, std::size_t max_bytes);

}  // namespace fw::server
