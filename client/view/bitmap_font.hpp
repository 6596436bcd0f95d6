#pragma once
// A built-in 5x7 pixel font (with one row more for the descenders of g, j,
// p, q, y) for the text the room view draws into its frames (names, the
// chat caption): the frames are rendered offscreen, where there is no font.
// Printable ASCII only; any other character is a box.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace fw::client {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 8;  ///< capitals 7 rows, descenders one more
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  ///< one pixel between letters

/// The glyph of `code_point`: five columns, left to right, bit 0 the top row,
/// bit 7 the descender row.
/// Characters outside printable ASCII get the placeholder box.
const std::array<std::uint8_t, kGlyphWidth>& glyph(char32_t code_point);

/// The code points of UTF-8 `text`; a malformed byte counts as one character
/// (drawn as the box), so every byte is accounted for.
std::vector<char32_t> code_points(std::string_view text);

}  // namespace fw::client
