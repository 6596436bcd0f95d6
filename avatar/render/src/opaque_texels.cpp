#include "opaque_texels.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace fw::render {

OpaqueTexels::OpaqueTexels(const std::vector<MipLevel>& levels) {
  for (const MipLevel& level : levels) {
    Level out;
    out.width = level.width;
    out.height = level.height;
    const std::size_t stride = static_cast<std::size_t>(level.width) + 1;
    out.translucent_sum.assign(stride * (static_cast<std::size_t>(level.height) + 1), 0);
    for (int y = 0; y < level.height; ++y)
      for (int x = 0; x < level.width; ++x) {
        const std::size_t texel = (static_cast<std::size_t>(y) * level.width + x) * 4;
        const std::uint32_t translucent = level.texels[texel + 3] < 255 ? 1 : 0;
        const std::size_t at = (y + 1) * stride + (x + 1);
        out.translucent_sum[at] = translucent + out.translucent_sum[at - 1] + out.translucent_sum[at - stride] -
                                  out.translucent_sum[at - stride - 1];
      }
    levels_.push_back(std::move(out));
  }
}

int OpaqueTexels::opaque_levels(glm::vec2 low, glm::vec2 high) const {
  int count = 0;
  for (const Level& level : levels_) {
    // Texel i's centre is at (i + 0.5) / size; a bilinear read at u takes
    // floor(u * size - 0.5) and the texel after it, clamped to the edge.
    const auto texel = [](float u, int size, int offset) {
      const float at = std::floor(u * static_cast<float>(size) - 0.5f) + static_cast<float>(offset);
      return static_cast<int>(std::clamp(at, 0.0f, static_cast<float>(size - 1)));
    };
    const int x0 = texel(low.x, level.width, -kTexelMargin), x1 = texel(high.x, level.width, 1 + kTexelMargin);
    const int y0 = texel(low.y, level.height, -kTexelMargin), y1 = texel(high.y, level.height, 1 + kTexelMargin);
    const std::size_t stride = static_cast<std::size_t>(level.width) + 1;
    const auto sum = [&](int x, int y) { return level.translucent_sum[static_cast<std::size_t>(y) * stride + x]; };
    if (sum(x1 + 1, y1 + 1) - sum(x0, y1 + 1) - sum(x1 + 1, y0) + sum(x0, y0) != 0) break;
    ++count;
  }
  return count;
}

glm::vec2 OpaqueTexels::size() const {
  return levels_.empty() ? glm::vec2(0.0f) : glm::vec2(levels_[0].width, levels_[0].height);
}

bool TexelOpacity::all_opaque() const {
  return std::all_of(opaque_levels.begin(), opaque_levels.end(), [this](int n) { return n >= level_count; });
}

TexelOpacity texel_opacity(const std::vector<glm::uvec3>& triangles, std::span<const glm::vec2> uvs,
                           const OpaqueTexels& texels) {
  TexelOpacity out;
  out.triangles = triangles;
  out.texture_size = texels.size();
  out.level_count = texels.level_count();
  for (const glm::uvec3& t : triangles) {
    const bool known = t.x < uvs.size() && t.y < uvs.size() && t.z < uvs.size();
    out.opaque_levels.push_back(known ? texels.opaque_levels(glm::min(uvs[t.x], glm::min(uvs[t.y], uvs[t.z])),
                                                             glm::max(uvs[t.x], glm::max(uvs[t.y], uvs[t.z])))
                                      : 0);
  }
  return out;
}

int highest_level_read(const std::array<glm::vec3, 3>& corners, const std::array<glm::vec2, 3>& uvs,
                       glm::vec2 texture_size, int level_count, const glm::mat4& mvp, glm::vec2 viewport) {
  const int last = std::max(level_count - 1, 0);
  std::array<glm::vec2, 3> pixel;
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::vec4 clip = mvp * glm::vec4(corners[i], 1.0f);
    if (!(clip.w > 1e-6f)) return last;
    pixel[i] = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * viewport;
  }
  const glm::vec2 e1 = pixel[1] - pixel[0], e2 = pixel[2] - pixel[0];
  const glm::vec2 t1 = (uvs[1] - uvs[0]) * texture_size, t2 = (uvs[2] - uvs[0]) * texture_size;
  const float det = e1.x * e2.y - e1.y * e2.x;
  if (!(std::abs(det) > 1e-3f)) return last;
  // Texels per pixel along the screen's x and y (the map from pixels to
  // texels is affine across a triangle but for perspective, which the
  // margin below covers).
  const glm::vec2 per_x = (t1 * e2.y - t2 * e1.y) / det, per_y = (t2 * e1.x - t1 * e2.x) / det;
  const float rho = std::max(glm::length(per_x), glm::length(per_y));
  const float lod = rho > 0.0f ? std::log2(rho) : -1.0f;
  // Trilinear filtering reads the level below the lod and the one above;
  // one more for llvmpipe's level per 2x2 quad and for perspective.
  const int highest = static_cast<int>(std::floor(lod)) + 2;
  return std::clamp(highest, 0, last);
}

std::size_t sort_opaque_first(const TexelOpacity& opacity, std::span<const glm::vec3> positions,
                              std::span<const glm::vec2> uvs, const glm::mat4& mvp, glm::vec2 viewport,
                              std::vector<glm::uvec3>& sorted) {
  sorted.clear();
  std::vector<glm::uvec3> translucent;
  for (std::size_t i = 0; i < opacity.triangles.size(); ++i) {
    const glm::uvec3 t = opacity.triangles[i];
    bool opaque = opacity.opaque_levels[i] >= opacity.level_count;
    if (!opaque && opacity.opaque_levels[i] > 0 && t.x < positions.size() && t.y < positions.size() &&
        t.z < positions.size() && t.x < uvs.size() && t.y < uvs.size() && t.z < uvs.size()) {
      const int highest = highest_level_read({positions[t.x], positions[t.y], positions[t.z]},
                                             {uvs[t.x], uvs[t.y], uvs[t.z]}, opacity.texture_size,
                                             opacity.level_count, mvp, viewport);
      opaque = opacity.opaque_levels[i] > highest;
    }
    (opaque ? sorted : translucent).push_back(t);
  }
  const std::size_t opaque_count = sorted.size();
  sorted.insert(sorted.end(), translucent.begin(), translucent.end());
  return opaque_count;
}

}  // namespace fw::render
