#pragma once
// Where on screen a part of a face can land, so that llvmpipe is given less
// to do: under multisampling it shades every fragment it rasterises, hidden
// or not, and a frame's clear, resolve and read-back cost by the pixel.
// - What lies behind an opening of the skin (an eyeball behind its eye
//   hole, the mouth cavity behind the lips) can be seen only through the
//   opening: its draw is scissored to the opening's rectangle, grown by a
//   quarter (the texture's alpha may open the skin a little beyond the
//   mesh's outline).
// - A frame's faces lie within their heads' boxes: the resolve and the
//   read-back cover only those boxes' rectangle.
#include <optional>
#include <span>

#include <glm/glm.hpp>

namespace fw::render {

/// A rectangle of pixels in GL's window coordinates (origin bottom left).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

/// The rectangle, within a width x height image, that holds `points` (model
/// space) seen through `model_view_projection`, grown on every side by
/// `grow` times its size and two pixels (a pixel at the border is covered
/// in part). nullopt when a point lies behind the camera: its projection
/// would be meaningless, so the caller must take the whole image.
std::optional<PixelRect> screen_rect(std::span<const glm::vec3> points, const glm::mat4& model_view_projection,
                                     int width, int height, float grow);

/// The smallest rectangle holding both.
PixelRect union_of(const PixelRect& a, const PixelRect& b);

}  // namespace fw::render
