#pragma once
// The point a head turns about, shared by what draws a head (avatar/render,
// the browser's engine) and what simulates its tissue in the head's frame
// (avatar/physics, whose loads from a turning head grow with the distance
// from it).
#include <glm/vec3.hpp>

namespace fw::model {

/// The top of the neck, below the ears, level with them in depth (the face
/// surface reaches about z = 2.2 at the nose), model units.
inline constexpr glm::vec3 kNeckPivot{0.0f, -1.5f, 0.2f};

}  // namespace fw::model
