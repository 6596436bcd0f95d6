#pragma once
// Masks of the skin regions whose colour changes with blood flow (MPCA in
// the vascular-expressions paper): each region's shape is a bicubic Bezier
// patch laid over the face, and its shade a bicubic Bezier function over
// the patch's parameters, 0 at the patch border and 1 at its heart, so
// blushes fade out smoothly.
#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "thin_plate_spline.hpp"

namespace fw::photo {

/// Regions in the order of codec::ColourRegion, then the whole face.
enum class MaskRegion { forehead, cheek_left, cheek_right, nose, sides, face, count };
inline constexpr std::size_t kMaskRegionCount = static_cast<std::size_t>(MaskRegion::count);

/// A bicubic Bezier patch: control points P[i][j] (i along u, j along v).
using BezierPatch = std::array<std::array<glm::vec2, 4>, 4>;

/// The patches of a region on the generic face (template frame); "sides"
/// has one per side, the others one.
std::vector<BezierPatch> region_patches(MaskRegion region);

/// Point of `patch` at (u, v) in [0,1]^2.
glm::vec2 evaluate_patch(const BezierPatch& patch, float u, float v);

/// The shade at (u, v): a bicubic Bezier function with control values
/// a_i a_j, a = (0, 1, 1, 0), normalised to 1 at the centre.
float evaluate_shade(float u, float v);

/// Scan-converts every region's patches, carried onto this face by `warp`,
/// into `size` x `size` masks (0..255) over the texture frame, rows top down.
std::array<cv::Mat, kMaskRegionCount> render_region_masks(const ThinPlateSpline& warp,
                                                          const model::TextureFrame& frame, int size);

/// The skin tone (sRGB): per-channel median of the texture where the
/// forehead and cheek masks are strong.
std::array<std::uint8_t, 3> estimate_skin_tone(const cv::Mat& texture, const std::array<cv::Mat, kMaskRegionCount>& masks);

}  // namespace fw::photo
