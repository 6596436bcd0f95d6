#pragma once
// Text drawn into a rendered frame with the built-in font (bitmap_font.hpp):
// light letters with a dark outline, readable over faces and background.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "fw/model/image.hpp"

namespace fw::client {

using Rgb = std::array<std::uint8_t, 3>;

/// Pixels across `text` at `scale` (each font pixel a scale x scale block).
int text_width(std::string_view text, int scale);
/// Pixels from the top of a line to its bottom, outline included.
int text_height(int scale);

/// `text` cut to at most `max_width` pixels, with "..." where it was cut.
std::string fit_text(std::string_view text, int max_width, int scale);

/// Draws `text` with its top left corner at (x, y) (the outline reaches one
/// font pixel further); what falls outside the image is left out.
void draw_text(model::RgbaImage& image, int x, int y, std::string_view text, int scale, Rgb colour);

}  // namespace fw::client
