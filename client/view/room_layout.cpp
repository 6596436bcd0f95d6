#include "room_layout.hpp"

#include <algorithm>
#include <cmath>

#include "first_person_layout.hpp"

namespace fw::client {
namespace {

// The layout depends on the frame's shape; any size of that shape will do.
FirstPersonLayout layout_for(int count, float aspect) {
  constexpr int kHeight = 360;
  const int width = std::max(16, static_cast<int>(std::lround(aspect * kHeight)));
  return first_person_layout(std::max(count - 1, 0), width, kHeight);
}

}  // namespace

std::vector<glm::mat4> room_places(int count, float aspect) {
  if (count <= 0) return {};
  const FirstPersonLayout layout = layout_for(count, aspect);
  std::vector<glm::mat4> places = layout.places;
  places.push_back(layout.self_place);
  return places;
}

render::Camera room_camera(int count, float aspect) { return layout_for(count, aspect).camera; }

glm::vec3 face_centre(const glm::mat4& place) {
  // Nose bridge height, a little under the eye line (eyes at y ~ 0), on the
  // skin in front of the head's centre.
  return glm::vec3(place * glm::vec4(0.0f, -0.3f, 1.6f, 1.0f));
}

}  // namespace fw::client
