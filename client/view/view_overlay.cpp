#include "view_overlay.hpp"

#include <algorithm>

#include "bitmap_font.hpp"
#include "frame_text.hpp"
#include "head_points.hpp"

namespace fw::client {
namespace {

constexpr Rgb kNameColour = {236, 236, 240};
constexpr Rgb kCaptionColour = {255, 236, 160};
constexpr Rgb kTileFrame = {200, 200, 210};

int margin_of(const model::RgbaImage& image) { return std::max(2, image.height / 60); }

}  // namespace

int text_scale(int height) { return std::max(1, (height + 100) / 240); }

void draw_name_under(model::RgbaImage& image, const render::Camera& camera, const glm::mat4& place, const std::string& name) {
  const glm::vec3 chin = render::project_to_pixel(camera, glm::vec3(place * glm::vec4(head_points().chin, 1.0f)),
                                                   image.width, image.height);
  const glm::vec3 side = render::project_to_pixel(
      camera, glm::vec3(place * glm::vec4(head_points().half_width, head_points().chin.y, 0.0f, 1.0f)), image.width,
      image.height);
  const int scale = text_scale(image.height);
  // As wide as the head, or a little more: neighbours' names must not run together.
  const int room = std::max(6 * kGlyphAdvance * scale, static_cast<int>(2.3f * std::abs(side.x - chin.x)));
  const std::string shown = fit_text(name, room, scale);
  const int x = static_cast<int>(chin.x) - text_width(shown, scale) / 2;
  draw_text(image, x, static_cast<int>(chin.y) + 3 * scale, shown, scale, kNameColour);
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
