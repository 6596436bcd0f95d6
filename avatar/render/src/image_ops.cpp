#include "fw/render/image_ops.hpp"

#include <algorithm>
#include <cmath>

namespace fw::render {

void draw_dot(model::RgbaImage& image, glm::vec2 centre, float radius, glm::u8vec3 colour) {
  const int x0 = std::max(0, static_cast<int>(std::floor(centre.x - radius)));
  const int x1 = std::min(image.width - 1, static_cast<int>(std::ceil(centre.x + radius)));
  const int y0 = std::max(0, static_cast<int>(std::floor(centre.y - radius)));
  const int y1 = std::min(image.height - 1, static_cast<int>(std::ceil(centre.y + radius)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const float dx = static_cast<float>(x) + 0.5f - centre.x, dy = static_cast<float>(y) + 0.5f - centre.y;
      if (dx * dx + dy * dy > radius * radius) continue;
      std::uint8_t* p = image.at(x, y);
      p[0] = colour.r, p[1] = colour.g, p[2] = colour.b, p[3] = 255;
    }
}

void paste(model::RgbaImage& target, const model::RgbaImage& source, int x, int y) {
  for (int sy = 0; sy < source.height; ++sy)
    for (int sx = 0; sx < source.width; ++sx) {
      const int tx = x + sx, ty = y + sy;
      if (tx < 0 || ty < 0 || tx >= target.width || ty >= target.height) continue;
      const std::uint8_t* s = source.at(sx, sy);
      std::uint8_t* t = target.at(tx, ty);
      const int a = s[3];
      for (int c = 0; c < 3; ++c) t[c] = static_cast<std::uint8_t>((s[c] * a + t[c] * (255 - a) + 127) / 255);
      t[3] = static_cast<std::uint8_t>(std::max<int>(t[3], a));
    }
}

model::RgbaImage resized(const model::RgbaImage& source, int width, int height) {
  model::RgbaImage out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float fx = std::clamp((static_cast<float>(x) + 0.5f) * static_cast<float>(source.width) / static_cast<float>(width) - 0.5f, 0.0f, static_cast<float>(source.width - 1));
      const float fy = std::clamp((static_cast<float>(y) + 0.5f) * static_cast<float>(source.height) / static_cast<float>(height) - 0.5f, 0.0f, static_cast<float>(source.height - 1));
      const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
      const int x1 = std::min(x0 + 1, source.width - 1), y1 = std::min(y0 + 1, source.height - 1);
      const float ax = fx - static_cast<float>(x0), ay = fy - static_cast<float>(y0);
      for (int c = 0; c < 4; ++c) {
        const float top = source.at(x0, y0)[c] * (1 - ax) + source.at(x1, y0)[c] * ax;
        const float bottom = source.at(x0, y1)[c] * (1 - ax) + source.at(x1, y1)[c] * ax;
        out.at(x, y)[c] = static_cast<std::uint8_t>(std::lround(top * (1 - ay) + bottom * ay));
      }
    }
  return out;
}

}  // namespace fw::render
