#include "room_layout.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace fw::client {
namespace {

// The seats of behavior::seat_layout (avatar/behavior/seat_layout.cpp),
// which the server's gaze is computed for; the client may not link
// behavior, so the numbers are repeated here and tests/client compares the
// two. Neighbours sit 420 mm apart, at most 50 degrees apart on the arc.
constexpr float kSeatSpacingUnits = 420.0f / 63.0f;  // millimetres / model::kMillimetresPerUnit
constexpr float kSeatAngleRad = 0.8726646f;           // 50 degrees
// behavior spreads a large room over up to 270 degrees; seen from one
// viewpoint the outer faces would turn their backs. Past 120 degrees the
// client narrows the arc so every face stays in view (gaze is then exact
// for the neighbours and approximate across the room).
constexpr float kMaxSpanRad = 2.0943951f;  // 120 degrees
constexpr float kHeadWidth = 3.4f;          // a head with its rim, model units (as place_in_row)

struct Arc {
  float radius = 0;  // from the point the avatars face
  float step_rad = 0;
};

Arc arc_for(int count) {
  if (count <= 1) return {};
  const float step = std::min(kSeatAngleRad, kMaxSpanRad / static_cast<float>(count - 1));
  // Neighbours one seat spacing apart along the chord.
  return {0.5f * kSeatSpacingUnits / std::sin(0.5f * step), step};
}

}  // namespace

std::vector<glm::mat4> room_places(int count) {
  std::vector<glm::mat4> places;
  if (count <= 0) return places;
  const Arc arc = arc_for(count);
  for (int i = 0; i < count; ++i) {
    // Angle from the arc's middle; negative on the viewer's left.
    const float angle = (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * arc.step_rad;
    // The arc's centre lies `radius` in front of the middle avatar (toward
    // the viewer); each avatar stands on the circle and turns to face it.
    const glm::vec3 position{arc.radius * std::sin(angle), 0.0f, arc.radius * (1.0f - std::cos(angle))};
    glm::mat4 place = glm::translate(glm::mat4(1.0f), position);
    places.push_back(glm::rotate(place, -angle, glm::vec3(0.0f, 1.0f, 0.0f)));
  }
  return places;
}

render::Camera room_camera(int count, float aspect) {
  render::Camera camera = render::Camera::portrait(aspect);
  if (count <= 1) return camera;
  const std::vector<glm::mat4> places = room_places(count);
  const glm::vec3 outer = glm::vec3(places.back()[3]);
  // The outer heads stand nearer the viewer: fit their width (plus a margin
  // of half a head) at their depth, and the middle head's height.
  const float half_width = outer.x + 0.5f * kHeadWidth + 0.3f;
  const float tan_half = std::tan(0.5f * camera.fov_y_rad);
  const float distance_for_width = half_width / (tan_half * aspect);
  camera.position.z = std::max(camera.position.z, outer.z + distance_for_width);
  return camera;
}

glm::vec3 face_centre(const glm::mat4& place) {
  // Nose bridge height, a little under the eye line (eyes at y ~ 0), on the
  // skin in front of the head's centre.
  return glm::vec3(place * glm::vec4(0.0f, -0.3f, 1.6f, 1.0f));
}

}  // namespace fw::client
