#pragma once
// Masks of the skin regions whose colour changes with blood flow (MPCA in
// the vascular-expressions paper): each region's shape is a bicubic Bezier
// patch laid over the face, its shade a bicubic Bezier function over the
// patch's parameters, 0 at the patch border and 1 at its heart, so blushes
// fade out smoothly. Computed here so that photo avatars (whose patches
// follow the fit) and procedural faces get the same regions.
#include <array>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/model/image.hpp"

namespace fw::model {

/// Regions in codec::ColourRegion order, then the whole face.
enum class MaskRegion { forehead, cheek_left, cheek_right, nose, sides, face, count };
inline constexpr std::size_t kMaskRegionCount = static_cast<std::size_t>(MaskRegion::count);

/// A bicubic Bezier patch: control points P[i][j] (i along u, j along v).
using BezierPatch = std::array<std::array<glm::vec2, 4>, 4>;

/// The patches of a region on the generic face (model frame); "sides" has
/// one per side, the others one.
std::vector<BezierPatch> region_patches(MaskRegion region);

/// Point of `patch` at (u, v) in [0,1]^2.
glm::vec2 evaluate_patch(const BezierPatch& patch, float u, float v);

/// The shade at (u, v): a bicubic Bezier function with control values
/// a_i a_j, a = (0, 1, 1, 0), normalised to 1 at the centre.
float evaluate_shade(float u, float v);

/// One 8-bit mask per region, `size` x `size` over the texture frame (rows
/// top down), with the patches carried onto a face by `warp` (generic model
/// frame -> this face's).
using Mask = std::vector<std::uint8_t>;
std::array<Mask, kMaskRegionCount> render_region_masks(const std::function<glm::vec2(glm::vec2)>& warp,
                                                       const TextureFrame& frame, int size);

/// The two mask images an avatar carries: a = (forehead, cheek_left,
/// cheek_right) in red, green, blue; b = (nose, sides, face).
std::array<RgbaImage, 2> pack_region_masks(const std::array<Mask, kMaskRegionCount>& masks, int size);

}  // namespace fw::model
