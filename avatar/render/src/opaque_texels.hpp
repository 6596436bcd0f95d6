#pragma once
// Which triangles of a mesh read only opaque texels in a frame, so that they
// can be drawn without alpha to coverage. With multisampling, llvmpipe turns
// a fragment's alpha into the share of its samples covered for every
// fragment of a draw that has it on, and it also moves the depth writes
// after the shader: 12 % of a frame (one face at 256x256, counted with
// callgrind). Where every texel a triangle's fragments can read has alpha
// 255, the filtered alpha is exactly 1, every sample is covered either way,
// and the triangle draws the same pixels without it; the triangles near an
// eye hole or a photo's matte keep it.
//
// Which texels a fragment reads depends on its mip level, and the small
// levels average the eye holes into every texel: a triangle is opaque for a
// frame only up to the level its size on screen selects (found per frame
// from its projection), plus one for trilinear filtering and one for
// llvmpipe's per-quad level and perspective.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "colour_mipmaps.hpp"

namespace fw::render {

/// Where a texture is opaque: per mip level, a summed-area table of its
/// texels whose alpha is below 255.
class OpaqueTexels {
 public:
  OpaqueTexels() = default;
  /// @param[in] levels  every mip level of the texture (bottom row first, as uploaded)
  explicit OpaqueTexels(const std::vector<MipLevel>& levels);

  /// How many levels, from level 0 on, hold only opaque texels wherever a
  /// fragment interpolating uvs within [low, high] can read (a bilinear
  /// footprint, kTexelMargin texels more on each side: a fragment is shaded
  /// at its pixel's centre, which may lie outside its triangle).
  int opaque_levels(glm::vec2 low, glm::vec2 high) const;
  /// Level 0's width and height in texels.
  glm::vec2 size() const;
  int level_count() const { return static_cast<int>(levels_.size()); }

  /// A pixel's centre lies within 0.71 pixels of a covered sample, so its
  /// uv lies at most about two texels of a level it reads beyond the
  /// triangle; bilinear filtering reads one more.
  static constexpr int kTexelMargin = 3;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<std::uint32_t> translucent_sum;  // (width + 1) x (height + 1)
  };
  std::vector<Level> levels_;
};

/// A mesh's triangles, each with how many levels of its texture it reads
/// only opaque texels from (OpaqueTexels::opaque_levels of its uvs' box).
struct TexelOpacity {
  std::vector<glm::uvec3> triangles;
  std::vector<int> opaque_levels;  ///< per triangle
  glm::vec2 texture_size{0.0f};    ///< level 0, texels
  int level_count = 0;
  /// Whether every triangle reads only opaque texels at every level.
  bool all_opaque() const;
};
TexelOpacity texel_opacity(const std::vector<glm::uvec3>& triangles, std::span<const glm::vec2> uvs,
                           const OpaqueTexels& texels);

/// The highest mip level a fragment of the triangle with these corners
/// (model space) and uvs can read, drawn through `mvp` into a `viewport`
/// (pixels); the last level when it cannot be told (a corner behind the
/// camera, a triangle seen edge on).
int highest_level_read(const std::array<glm::vec3, 3>& corners, const std::array<glm::vec2, 3>& uvs,
                       glm::vec2 texture_size, int level_count, const glm::mat4& mvp, glm::vec2 viewport);

/// The triangles of `opacity` that read only opaque texels in this frame
/// first, then the rest, into `sorted`; returns how many are opaque.
std::size_t sort_opaque_first(const TexelOpacity& opacity, std::span<const glm::vec3> positions,
                              std::span<const glm::vec2> uvs, const glm::mat4& mvp, glm::vec2 viewport,
                              std::vector<glm::uvec3>& sorted);

}  // namespace fw::render
