#pragma once
// How many pixels of a rendered image, within a box, a test's predicate
// picks: the measure behind "the letters are drawn", "skin fills the tile",
// "the head covers as much turned as facing". The box is clipped to the
// image, so a test can name one that reaches past an edge.
#include <algorithm>
#include <cstdint>

#include "fw/model/image.hpp"

namespace fw::test {

/// A half-open box of pixels: x in [x0, x1), y in [y0, y1).
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 1 << 20, y1 = 1 << 20;
};

/// Pixels in `box` for which `pick(const std::uint8_t* rgba)` is true.
template <typename Pick>
int count_pixels(const model::RgbaImage& image, Pick pick, PixelBox box = {}) {
  int n = 0;
  for (int y = std::max(0, box.y0); y < std::min(image.height, box.y1); ++y)
    for (int x = std::max(0, box.x0); x < std::min(image.width, box.x1); ++x) n += pick(image.at(x, y)) ? 1 : 0;
  return n;
}

}  // namespace fw::test
