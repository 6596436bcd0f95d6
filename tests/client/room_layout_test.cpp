#include "room_layout.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

TEST(RoomLayout, OneAvatarFacesTheViewerFromTheOrigin) {
  const auto places = room_places(1);
  ASSERT_EQ(places.size(), 1u);
  EXPECT_EQ(places[0], glm::mat4(1.0f));
}

TEST(RoomLayout, AvatarsStandLeftToRightAndTurnTowardTheMiddle) {
  for (int count : {2, 3, 5, 8, 16}) {
    const auto places = room_places(count);
    ASSERT_EQ(places.size(), static_cast<std::size_t>(count));
    for (int i = 1; i < count; ++i) EXPECT_LT(places[i - 1][3].x, places[i][3].x) << count;
    // The face's forward direction (+z in model space) points toward x = 0.
    const glm::vec3 left_forward = glm::vec3(places.front() * glm::vec4(0, 0, 1, 0));
    const glm::vec3 right_forward = glm::vec3(places.back() * glm::vec4(0, 0, 1, 0));
    EXPECT_GT(left_forward.x, 0.1f) << count;
    EXPECT_LT(right_forward.x, -0.1f) << count;
    EXPECT_GE(left_forward.z, 0.49f) << "faces stay turned at most 60 degrees from the viewer: " << count;
  }
}

TEST(RoomLayout, TheCameraSeesEveryFace) {
  for (int count : {1, 2, 3, 8, 12}) {
    const float aspect = 16.0f / 9.0f;
    const auto camera = room_camera(count, aspect);
    const auto places = room_places(count);
    float last_x = -1;
    for (const auto& place : places) {
      const glm::vec3 p = render::project_to_pixel(camera, face_centre(place), 640, 360);
      EXPECT_GT(p.x, 0);
      EXPECT_LT(p.x, 640);
      EXPECT_GT(p.y, 0);
      EXPECT_LT(p.y, 360);
      EXPECT_GT(p.x, last_x + 20) << "faces do not overlap on screen: " << count;
      last_x = p.x;
    }
  }
}

}  // namespace
}  // namespace fw::client
