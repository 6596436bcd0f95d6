#pragma once
// The room as one person sees it from their own place at the table: the
// others on an arc in front of the viewer's eyes (the camera), each turned to
// face the viewer, large enough that up to six of them stay at least 120
// pixels tall in a 640x360 frame; and the viewer's own face small in a
// corner tile, as a video call's self view. Plain geometry: no renderer, no
// socket.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fw/codec/messages.hpp"
#include "fw/render/camera.hpp"

namespace fw::client {

/// A rectangle of the image in pixels (x right, y down).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(int px, int py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

struct FirstPersonLayout {
  render::Camera camera;  ///< at the viewer's eyes
  /// The others' places (model matrices before each head's own pose), left
  /// to right as the viewer sees them, each facing the camera.
  std::vector<glm::mat4> places;
  /// The self view: its tile and the place of the viewer's own face, small
  /// and close to the camera, so that the one render pass draws it there.
  PixelRect self_tile;
  glm::mat4 self_place{1.0f};
};

/// The layout of `others` faces (0 .. 64) in a width x height image.
FirstPersonLayout first_person_layout(int others, int width, int height);

/// The others of `viewer` in the order they sit at the table as the viewer
/// sees it, left to right: by their server seats' places along the arc (not
/// their facings, which the server may give alike; neighbours stay
/// neighbours), ties by id. `avatars` may include the viewer (left out).
struct SeatedAvatar {
  std::uint32_t id = 0;
  codec::SeatInfo seat;
};
std::vector<std::uint32_t> others_left_to_right(std::vector<SeatedAvatar> avatars, std::uint32_t viewer);

/// Where the viewer's eyes are: the point faces attending the viewer look at.
inline glm::vec3 viewer_eyes(const FirstPersonLayout& layout) { return layout.camera.position; }

}  // namespace fw::client
