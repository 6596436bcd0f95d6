#pragma once
// What lies behind an opening of the skin (an eyeball behind its eye hole,
// the mouth cavity behind the lips) can be seen only through the opening,
// so its draw is scissored to the opening's rectangle on screen: under
// multisampling llvmpipe shades every fragment it rasterises, hidden or not,
// and most of an eyeball or of the mouth cavity is hidden behind the skin.
#include <optional>
#include <span>

#include <glm/glm.hpp>

namespace fw::render {

/// A rectangle of pixels in GL's window coordinates (origin bottom left).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

/// The rectangle, within a width x height image, that holds the outline
/// `points` (model space) seen through `model_view_projection`, grown on
/// every side by a quarter of its size and two pixels: the texture's alpha
/// may open the skin a little beyond the mesh's outline, and a pixel at the
/// border is covered in part. nullopt when a point lies behind the camera
/// (its projection would be meaningless: draw without a scissor).
std::optional<PixelRect> opening_rect(std::span<const glm::vec3> points, const glm::mat4& model_view_projection,
                                      int width, int height);

}  // namespace fw::render
