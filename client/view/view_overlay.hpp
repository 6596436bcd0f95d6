#pragma once
// What the room view draws over its rendered frame: each face's neck faded
// out and its name under its chin, the self view's frame (and the photo in it until the viewer's
// own face is there), the last chat line as a caption.
#include <string>

#include <glm/mat4x4.hpp>

#include "first_person_layout.hpp"
#include "fw/model/image.hpp"
#include "fw/render/camera.hpp"

namespace fw::client {

/// The scale of the font (font pixels per image pixel) in a frame `height` tall.
int text_scale(int height);

/// Fades the neck of the face standing at `place` into `background` (the
/// renderer's, sRGB [0,1]) from a little under its chin down, so that the
/// face ends there and the name under it reads as its caption rather than
/// a label on a long neck (as the browser's tiles do, web/room/face_frame.js).
void fade_neck(model::RgbaImage& image, const render::Camera& camera, const glm::mat4& place, glm::vec3 background);

/// `name`, centred under the chin of the face standing at `place`, where
/// fade_neck has cleared the neck.
void draw_name_under(model::RgbaImage& image, const render::Camera& camera, const glm::mat4& place, const std::string& name);

/// The self view's frame, with `name` in its bottom left corner.
void draw_self_tile(model::RgbaImage& image, const PixelRect& tile, const std::string& name);

/// The pixels of `tile` from `from` into `image` (both the same size).
void copy_tile(const model::RgbaImage& from, const PixelRect& tile, model::RgbaImage& image);

/// `photo` filling `tile` (its middle cut out to the tile's shape).
void draw_photo_in_tile(model::RgbaImage& image, const model::RgbaImage& photo, const PixelRect& tile);

/// The caption's box: the bottom left of the frame, left of the self view.
PixelRect caption_box(const model::RgbaImage& image, const PixelRect& tile);
/// `caption` in the caption box (cut to fit); nothing when it is empty.
void draw_caption(model::RgbaImage& image, const PixelRect& tile, const std::string& caption);

}  // namespace fw::client
