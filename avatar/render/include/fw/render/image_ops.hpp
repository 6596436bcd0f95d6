#pragma once
// Small drawing operations for contact sheets and previews.
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/model/image.hpp"

namespace fw::render {

/// A filled disc of `radius` pixels at `centre` (x right, y down), clipped.
void draw_dot(model::RgbaImage& image, glm::vec2 centre, float radius, glm::u8vec3 colour);

/// Copies `source` into `target` with its top-left corner at (x, y), clipped;
/// pixels are composited over what is there by the source's alpha.
void paste(model::RgbaImage& target, const model::RgbaImage& source, int x, int y);

/// `source` scaled to width x height (bilinear).
model::RgbaImage resized(const model::RgbaImage& source, int width, int height);

}  // namespace fw::render
