#pragma once
// Where a room's avatars stand: on an arc around a point in front of them,
// each turned toward that point, so they face one another as the three
// faces of the behavioral-animation paper's Figure 9 do, with the viewer
// looking in from the open side.
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fw/render/camera.hpp"

namespace fw::client {

/// The place (model matrix before the head's own pose) of each of `count`
/// avatars, left to right as the viewer sees them: translate(seat) *
/// rotate_y(facing). One avatar stands at the origin facing the viewer; more
/// sit on behavior::seat_layout's arc (up to three avatars exactly; larger
/// rooms on an arc narrowed to 120 degrees).
/// @param[in] count  0 .. 64
std::vector<glm::mat4> room_places(int count);

/// A camera that sees every avatar of room_places(count) whole.
/// @param[in] aspect  image width / height
render::Camera room_camera(int count, float aspect);

/// A point on the middle of the face standing at `place` (between the eyes
/// and the mouth, on the skin): where a rendered room must show that face.
glm::vec3 face_centre(const glm::mat4& place);

}  // namespace fw::client
