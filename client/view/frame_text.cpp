#include "frame_text.hpp"

#include <vector>

#include "bitmap_font.hpp"

namespace fw::client {
namespace {

void fill_block(model::RgbaImage& image, int x, int y, int size, Rgb colour) {
  for (int dy = 0; dy < size; ++dy)
    for (int dx = 0; dx < size; ++dx) {
      const int px = x + dx, py = y + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      std::uint8_t* p = image.at(px, py);
      p[0] = colour[0], p[1] = colour[1], p[2] = colour[2], p[3] = 255;
    }
}

// Calls `lit(x, y)` for every lit font pixel of `text` (font-pixel units,
// origin at the first letter's top left).
template <class Lit>
void for_each_lit(const std::vector<char32_t>& text, Lit lit) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto& columns = glyph(text[i]);
    for (int col = 0; col < kGlyphWidth; ++col)
      for (int row = 0; row < kGlyphHeight; ++row)
        if (columns[static_cast<std::size_t>(col)] & (1u << row)) lit(static_cast<int>(i) * kGlyphAdvance + col, row);
  }
}

}  // namespace

int text_width(std::string_view text, int scale) {
  const auto n = static_cast<int>(code_points(text).size());
  return n == 0 ? 0 : (n * kGlyphAdvance - 1) * scale;
}

int text_height(int scale) { return (kGlyphHeight + 2) * scale; }

std::string fit_text(std::string_view text, int max_width, int scale) {
  if (text_width(text, scale) <= max_width) return std::string(text);
  // Cut at a character boundary: drop whole UTF-8 sequences from the end.
  std::string cut(text);
  while (!cut.empty() && text_width(cut + "...", scale) > max_width) {
    cut.pop_back();
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();
    if (!cut.empty() && static_cast<unsigned char>(cut.back()) >= 0xC0) cut.pop_back();
  }
  return cut.empty() && text_width("...", scale) > max_width ? std::string() : cut + "...";
}

void draw_text(model::RgbaImage& image, int x, int y, std::string_view text, int scale, Rgb colour) {
  const std::vector<char32_t> points = code_points(text);
  constexpr Rgb kOutline = {16, 16, 20};
  // The outline first: every neighbour of a lit pixel, then the letters over it.
  for_each_lit(points, [&](int fx, int fy) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) fill_block(image, x + (fx + dx) * scale, y + (fy + dy) * scale, scale, kOutline);
  });
  for_each_lit(points, [&](int fx, int fy) { fill_block(image, x + fx * scale, y + fy * scale, scale, colour); });
}

}  // namespace fw::client
