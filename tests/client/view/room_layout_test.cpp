#include "room_layout.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

TEST(RoomLayout, AMemberSeesTheOthersThenItsSelfView) {
  EXPECT_TRUE(room_places(0).empty());
  for (int count : {1, 2, 3, 8, 16}) EXPECT_EQ(room_places(count).size(), static_cast<std::size_t>(count));
}

TEST(RoomLayout, TheCameraSeesEveryFaceAndNoTwoCoincide) {
  for (int count : {1, 2, 3, 8, 12}) {
    const float aspect = 16.0f / 9.0f;
    const auto camera = room_camera(count, aspect);
    const auto places = room_places(count, aspect);
    float last_x = -1;
    for (std::size_t i = 0; i < places.size(); ++i) {
      const glm::vec3 p = render::project_to_pixel(camera, face_centre(places[i]), 640, 360);
      EXPECT_GT(p.x, 0);
      EXPECT_LT(p.x, 640);
      EXPECT_GT(p.y, 0);
      EXPECT_LT(p.y, 360);
      if (i + 1 < places.size()) {
        EXPECT_GT(p.x, last_x + 20) << "the others side by side: " << count;
        last_x = p.x;
      } else {
        EXPECT_GT(p.y, 240) << "the self view, low in the frame";
      }
    }
  }
}

}  // namespace
}  // namespace fw::client
