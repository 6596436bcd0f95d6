#pragma once
// Whether a pixel lies well inside an outline projected onto an image (an
// eye opening, say): tests that look for an iris keep clear of the lid's
// dark rim this way.
#include <algorithm>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace fw::test {

/// Whether `c` lies inside `polygon` (even-odd rule), at least `inset` pixels from its edges.
inline bool inside_inset(const std::vector<glm::vec2>& polygon, glm::vec2 c, float inset) {
  bool in = false;
  float edge = 1e9f;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::vec2 a = polygon[i], b = polygon[j];
    if ((a.y > c.y) != (b.y > c.y) && c.x < (b.x - a.x) * (c.y - a.y) / (b.y - a.y) + a.x) in = !in;
    const float t = glm::clamp(glm::dot(c - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
    edge = std::min(edge, glm::length(c - (a + t * (b - a))));
  }
  return in && edge >= inset;
}

}  // namespace fw::test
