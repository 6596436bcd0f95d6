#pragma once
// Where the faces of a room of `count` avatars appear in the frames one of
// them renders (first_person_layout): the others on the arc in front, then
// the viewer's own face in the self view. For code that looks at the frames
// from outside, knowing only how many are in the room (the end-to-end
// tests): the view itself orders the others by their seats.
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fw/render/camera.hpp"

namespace fw::client {

/// The client's default frame shape (640x360).
inline constexpr float kDefaultAspect = 16.0f / 9.0f;

/// The places of the faces a member of a room of `count` (1 .. 65) sees,
/// in a frame of `aspect`: count - 1 others left to right, then the self view.
std::vector<glm::mat4> room_places(int count, float aspect = kDefaultAspect);

/// The camera of those frames.
render::Camera room_camera(int count, float aspect);

/// A point on the middle of the face standing at `place` (between the eyes
/// and the mouth, on the skin): where a rendered room must show that face.
glm::vec3 face_centre(const glm::mat4& place);

}  // namespace fw::client
