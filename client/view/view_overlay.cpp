#include "view_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "bitmap_font.hpp"
#include "frame_text.hpp"
#include "head_points.hpp"

namespace fw::client {
namespace {

constexpr Rgb kNameColour = {236, 236, 240};
constexpr Rgb kCaptionColour = {255, 236, 160};
constexpr Rgb kTileFrame = {200, 200, 210};

int margin_of(const model::RgbaImage& image) { return std::max(2, image.height / 60); }

// Where a face's neck fade starts and how long it is, in eye-to-chin heights
// below the chin: the fade clears the top of the neck, the name sits in it.
constexpr float kFadeStart = 0.1f, kFadeLength = 0.35f;

// The chin of the face at `place`, and the height from its eyes to its chin, in pixels.
struct ChinInFrame {
  glm::vec3 chin;
  float face_height;
};
ChinInFrame chin_in_frame(const model::RgbaImage& image, const render::Camera& camera, const glm::mat4& place) {
  const auto pixel = [&](glm::vec3 p) {
    return render::project_to_pixel(camera, glm::vec3(place * glm::vec4(p, 1.0f)), image.width, image.height);
  };
  const glm::vec3 chin = pixel(head_points().chin);
  return {chin, std::max(1.0f, chin.y - pixel(head_points().eye_mid).y)};
}

}  // namespace

int text_scale(int height) { return std::max(1, (height + 100) / 240); }

void fade_neck(model::RgbaImage& image, const render::Camera& camera, const glm::mat4& place, glm::vec3 background) {
  const ChinInFrame face = chin_in_frame(image, camera, place);
  const glm::vec3 side = render::project_to_pixel(
      camera, glm::vec3(place * glm::vec4(head_points().half_width, head_points().chin.y, 0.0f, 1.0f)), image.width,
      image.height);
  // The neck is narrower than the head: the head's width at the chin holds it however the head is turned.
  const float half = 1.2f * std::max(std::abs(side.x - face.chin.x), 0.3f * face.face_height);
  const float start = face.chin.y + kFadeStart * face.face_height, length = kFadeLength * face.face_height;
  const glm::vec3 to = background * 255.0f;
  const int x0 = std::max(0, static_cast<int>(face.chin.x - half));
  const int x1 = std::min(image.width, static_cast<int>(face.chin.x + half) + 1);
  for (int y = std::max(0, static_cast<int>(start)); y < image.height; ++y) {
    const float t = std::clamp((static_cast<float>(y) - start) / length, 0.0f, 1.0f);
    for (int x = x0; x < x1; ++x) {
      std::uint8_t* p = image.at(x, y);
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<std::uint8_t>(std::lround(static_cast<float>(p[c]) + t * (to[c] - static_cast<float>(p[c]))));
    }
  }
}

void draw_name_under(model::RgbaImage& image, const render::Camera& camera, const glm::mat4& place, const std::string& name) {
  const ChinInFrame face = chin_in_frame(image, camera, place);
  const glm::vec3 chin = face.chin;
  const glm::vec3 side = render::project_to_pixel(
      camera, glm::vec3(place * glm::vec4(head_points().half_width, head_points().chin.y, 0.0f, 1.0f)), image.width,
      image.height);
  const int scale = text_scale(image.height);
  // As wide as the head, or a little more: neighbours' names must not run together.
  const int room = std::max(6 * kGlyphAdvance * scale, static_cast<int>(2.3f * std::abs(side.x - chin.x)));
  const std::string shown = fit_text(name, room, scale);
  const int x = static_cast<int>(chin.x) - text_width(shown, scale) / 2;
  // In the fade, past its first third: on the background more than on the neck.
  const float below = (kFadeStart + 0.35f * kFadeLength) * face.face_height;
  draw_text(image, x, static_cast<int>(chin.y + below), shown, scale, kNameColour);
}

void draw_self_tile(model::RgbaImage& image, const PixelRect& tile, const std::string& name) {
  for (int x = tile.x - 1; x <= tile.x + tile.width; ++x)
    for (int y : {tile.y - 1, tile.y + tile.height})
      if (x >= 0 && y >= 0 && x < image.width && y < image.height) std::copy_n(kTileFrame.data(), 3, image.at(x, y));
  for (int y = tile.y - 1; y <= tile.y + tile.height; ++y)
    for (int x : {tile.x - 1, tile.x + tile.width})
      if (x >= 0 && y >= 0 && x < image.width && y < image.height) std::copy_n(kTileFrame.data(), 3, image.at(x, y));
  if (name.empty()) return;
  const int scale = text_scale(image.height);
  const std::string shown = fit_text(name, tile.width - 4 * scale, scale);
  draw_text(image, tile.x + 2 * scale, tile.y + tile.height - (kGlyphHeight + 2) * scale, shown, scale, kNameColour);
}

void copy_tile(const model::RgbaImage& from, const PixelRect& tile, model::RgbaImage& image) {
  if (from.width != image.width || from.height != image.height) return;
  const int x0 = std::max(0, tile.x), x1 = std::min(image.width, tile.x + tile.width);
  for (int y = std::max(0, tile.y); y < std::min(image.height, tile.y + tile.height); ++y)
    if (x1 > x0) std::copy_n(from.at(x0, y), 4 * (x1 - x0), image.at(x0, y));
}

void draw_photo_in_tile(model::RgbaImage& image, const model::RgbaImage& photo, const PixelRect& tile) {
  if (photo.width <= 0 || photo.height <= 0 || tile.width <= 0 || tile.height <= 0) return;
  // Cover the tile: the photo scaled to fill it, its middle kept.
  const float scale = std::max(static_cast<float>(tile.width) / static_cast<float>(photo.width),
                               static_cast<float>(tile.height) / static_cast<float>(photo.height));
  const float off_x = 0.5f * (static_cast<float>(photo.width) - static_cast<float>(tile.width) / scale);
  const float off_y = 0.5f * (static_cast<float>(photo.height) - static_cast<float>(tile.height) / scale);
  for (int y = 0; y < tile.height; ++y)
    for (int x = 0; x < tile.width; ++x) {
      const int ix = tile.x + x, iy = tile.y + y;
      if (ix < 0 || iy < 0 || ix >= image.width || iy >= image.height) continue;
      const int px = std::clamp(static_cast<int>(off_x + (static_cast<float>(x) + 0.5f) / scale), 0, photo.width - 1);
      const int py = std::clamp(static_cast<int>(off_y + (static_cast<float>(y) + 0.5f) / scale), 0, photo.height - 1);
      std::copy_n(photo.at(px, py), 3, image.at(ix, iy));
    }
}

PixelRect caption_box(const model::RgbaImage& image, const PixelRect& tile) {
  const int margin = margin_of(image);
  const int scale = text_scale(image.height);
  const int height = text_height(scale);
  return {margin + scale, image.height - margin - height, std::max(0, tile.x - 3 * margin), height};
}

void draw_caption(model::RgbaImage& image, const PixelRect& tile, const std::string& caption) {
  if (caption.empty()) return;
  const PixelRect box = caption_box(image, tile);
  const int scale = text_scale(image.height);
  draw_text(image, box.x, box.y + scale, fit_text(caption, box.width, scale), scale, kCaptionColour);
}

}  // namespace fw::client
