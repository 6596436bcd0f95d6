#include "screen_rect.hpp"

#include <algorithm>
#include <cmath>

namespace fw::render {

std::optional<PixelRect> screen_rect(std::span<const glm::vec3> points, const glm::mat4& model_view_projection,
                                     int width, int height, float grow) {
  if (points.empty()) return std::nullopt;
  glm::vec2 low(1e30f), high(-1e30f);
  for (const glm::vec3& p : points) {
    const glm::vec4 clip = model_view_projection * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;
    const glm::vec2 window = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
    low = glm::min(low, window);
    high = glm::max(high, window);
  }
  const glm::vec2 margin = grow * (high - low) + 2.0f;
  const auto clamp = [](float v, int limit) { return std::clamp(static_cast<int>(v), 0, limit); };
  const int x0 = clamp(std::floor(low.x - margin.x), width), x1 = clamp(std::ceil(high.x + margin.x), width);
  const int y0 = clamp(std::floor(low.y - margin.y), height), y1 = clamp(std::ceil(high.y + margin.y), height);
  return PixelRect{x0, y0, x1 - x0, y1 - y0};
}

PixelRect union_of(const PixelRect& a, const PixelRect& b) {
  if (a.width <= 0 || a.height <= 0) return b;
  if (b.width <= 0 || b.height <= 0) return a;
  const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace fw::render
