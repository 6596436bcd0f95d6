#include "first_person_layout.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec2.hpp>

#include "head_points.hpp"

namespace fw::client {
namespace {

// The others sit this far from the viewer's eyes (model units: about 1.3 m,
// across a table), further when many would spread past kMaxHalfSpanRad:
// a wider lens would stretch the outer faces.
constexpr float kArcRadius = 20.0f;
constexpr float kMaxHalfSpanRad = 0.5f;
// Neighbours' heads at least this many head widths apart, centre to centre
// (at most kMaxHeadSpacing when the frame has room): a head turned toward
// its neighbour must not run into it.
constexpr float kHeadSpacing = 1.08f;
constexpr float kMaxHeadSpacing = 1.6f;
// A lone face at most this share of the image's height (chin to crown),
// leaving room for its name, the caption and the self view below.
constexpr float kMaxFaceShare = 0.52f;
// The eye line this share of the height from the top: faces sit high, the
// caption and the self view use the bottom.
constexpr float kEyeLineShare = 0.34f;
// Pixels kept free at the image's left and right edges.
constexpr float kSideMarginShare = 0.01f;
// The self view: its tile's height as a share of the image's, 4:3, in the
// bottom right corner; the face inside it at this scale (small and close, so
// that it stays far in front of the arc in depth).
constexpr float kTileShare = 0.3f;
constexpr float kSelfScale = 0.1f;

float face_height() { return head_points().top.y - head_points().chin.y; }

// The head from its crown to a little under the chin, for the self view to
// fit in its tile (the neck below runs out of the tile's bottom edge).
float head_extent_y(float& low) {
  const HeadPoints& p = head_points();
  low = p.chin.y - 0.12f * (p.top.y - p.chin.y);
  return p.top.y - low;
}

glm::mat4 facing_camera(glm::vec3 position, glm::vec3 camera) {
  const glm::vec3 z = glm::normalize(camera - position);
  const glm::vec3 x = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), z));
  const glm::vec3 y = glm::cross(z, x);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x, 0.0f);
  m[1] = glm::vec4(y, 0.0f);
  m[2] = glm::vec4(z, 0.0f);
  m[3] = glm::vec4(position, 1.0f);
  return m;
}

}  // namespace

FirstPersonLayout first_person_layout(int others, int width, int height) {
  FirstPersonLayout layout;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const HeadPoints& head = head_points();
  const int n = std::clamp(others, 0, 64);

  // The angle between neighbours seen from the viewer, for a spacing in
  // head widths, and the outermost face's outer edge.
  const float half_width = head.half_width;
  const float radius = std::max(kArcRadius, static_cast<float>(n) * kHeadSpacing * half_width / kMaxHalfSpanRad);
  const auto step_for = [&](float spacing) { return 2.0f * std::asin(std::min(1.0f, spacing * half_width / radius)); };
  const auto outer_for = [&](float spacing) {
    return 0.5f * static_cast<float>(std::max(n - 1, 0)) * step_for(spacing) + std::atan(half_width / radius);
  };
  // The lens that keeps a lone face to kMaxFaceShare of the height; the
  // faces spread as far apart as it shows (up to kMaxHeadSpacing); when even
  // the closest spacing does not fit, a wider lens shows them all.
  const float tan_half_for_height = 0.5f * (face_height() / radius) / kMaxFaceShare;
  const float usable = 1.0f - 2.0f * kSideMarginShare;
  const float fits = std::atan(tan_half_for_height * aspect * usable);
  float spacing = kMaxHeadSpacing;
  while (spacing > kHeadSpacing && outer_for(spacing) > fits) spacing = std::max(kHeadSpacing, spacing - 0.02f);
  const float step = step_for(spacing);
  const float tan_half_for_width = std::tan(outer_for(spacing)) / usable / aspect;
  const float tan_half_y = std::max(tan_half_for_width, tan_half_for_height);

  render::Camera& camera = layout.camera;
  camera.aspect = aspect;
  camera.fov_y_rad = 2.0f * std::atan(tan_half_y);
  camera.near_plane = 0.2f;
  camera.far_plane = 2.0f * radius + 10.0f;
  camera.position = glm::vec3(0.0f, head.eye_mid.y, 0.0f);
  // Looking down a little puts the others' eye line at kEyeLineShare.
  const float down = (0.5f - kEyeLineShare) * 2.0f * tan_half_y;
  camera.target = camera.position + glm::vec3(0.0f, -down, -1.0f);

  for (int i = 0; i < n; ++i) {
    const float phi = (static_cast<float>(i) - 0.5f * static_cast<float>(n - 1)) * step;  // negative: viewer's left
    const glm::vec3 position{radius * std::sin(phi), 0.0f, -radius * std::cos(phi)};
    layout.places.push_back(glm::rotate(glm::translate(glm::mat4(1.0f), position), -phi, glm::vec3(0.0f, 1.0f, 0.0f)));
  }

  // The self view: a tile in the bottom right corner; the viewer's face on
  // the camera's ray through the tile's middle, facing the camera.
  const int tile_h = std::max(8, static_cast<int>(std::lround(kTileShare * static_cast<float>(height))));
  const int tile_w = std::min(width / 2, tile_h * 4 / 3);
  const int margin = std::max(2, height / 60);
  layout.self_tile = {width - tile_w - margin, height - tile_h - margin, tile_w, tile_h};
  float low = 0;
  const float extent = head_extent_y(low);
  const float head_pixels = 0.86f * static_cast<float>(tile_h);
  const float distance = kSelfScale * extent * static_cast<float>(height) / (2.0f * tan_half_y * head_pixels);
  const glm::vec2 centre_px{static_cast<float>(layout.self_tile.x) + 0.5f * static_cast<float>(tile_w),
                            static_cast<float>(layout.self_tile.y) + 0.5f * static_cast<float>(tile_h)};
  const glm::vec3 on_near = glm::unProject(glm::vec3(centre_px.x, static_cast<float>(height) - centre_px.y, 0.0f),
                                           camera.view(), camera.projection(), glm::vec4(0, 0, width, height));
  const glm::vec3 ray = glm::normalize(on_near - camera.position);
  // The point of the head at the tile's middle is the middle of its extent.
  const glm::vec3 middle_of_head(0.0f, low + 0.5f * extent, 0.0f);
  const glm::vec3 anchor = camera.position + distance * ray;
  glm::mat4 place = facing_camera(anchor, camera.position);
  place = glm::scale(place, glm::vec3(kSelfScale));
  layout.self_place = glm::translate(place, -middle_of_head);
  return layout;
}

std::vector<std::uint32_t> others_left_to_right(std::vector<SeatedAvatar> avatars, std::uint32_t viewer) {
  // The server's seats lie on an arc open toward the room's +z. Seen from
  // inside the arc (from any point of it), the seats keep their order along
  // it, so the angle about the seats' centroid (strictly inside the arc's
  // circle) orders them whatever their facings, which need not differ: two
  // seats may be turned alike. Measured from the arc's back (-z), larger
  // angles (toward +x) lie further to a seated person's left.
  glm::vec2 centroid(0.0f);
  for (const SeatedAvatar& a : avatars) centroid += glm::vec2(a.seat.x_mm, a.seat.z_mm);
  if (!avatars.empty()) centroid /= static_cast<float>(avatars.size());
  const auto around = [&](const codec::SeatInfo& s) { return std::atan2(s.x_mm - centroid.x, centroid.y - s.z_mm); };
  std::stable_sort(avatars.begin(), avatars.end(), [&](const SeatedAvatar& a, const SeatedAvatar& b) {
    const float ka = around(a.seat), kb = around(b.seat);
    if (ka != kb) return ka > kb;
    return a.id < b.id;
  });
  std::vector<std::uint32_t> order;
  for (const SeatedAvatar& a : avatars)
    if (a.id != viewer) order.push_back(a.id);
  return order;
}

}  // namespace fw::client
