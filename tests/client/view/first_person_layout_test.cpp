#include "first_person_layout.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "head_points.hpp"

namespace fw::client {
namespace {

glm::vec3 pixel(const FirstPersonLayout& layout, const glm::mat4& place, glm::vec3 p, int w, int h) {
  return render::project_to_pixel(layout.camera, glm::vec3(place * glm::vec4(p, 1.0f)), w, h);
}

TEST(FirstPersonLayout, UpToSixOthersAreEachAtLeast120PixelsTallAt640x360) {
  for (int others = 1; others <= 6; ++others) {
    const FirstPersonLayout layout = first_person_layout(others, 640, 360);
    ASSERT_EQ(layout.places.size(), static_cast<std::size_t>(others));
    for (const glm::mat4& place : layout.places) {
      const float top = pixel(layout, place, head_points().top, 640, 360).y;
      const float chin = pixel(layout, place, head_points().chin, 640, 360).y;
      EXPECT_GE(chin - top, 120.0f) << others << " others";
    }
  }
}

TEST(FirstPersonLayout, EveryFaceIsInViewAndNoneOverlaps) {
  for (int others : {1, 2, 3, 4, 5, 6, 9, 15}) {
    const FirstPersonLayout layout = first_person_layout(others, 640, 360);
    float right_of_last = -1e9f;
    for (const glm::mat4& place : layout.places) {
      const float w = head_points().half_width;
      // The person's right side (model -x) is on the viewer's left.
      const glm::vec3 left = pixel(layout, place, {-w, 0.0f, 0.0f}, 640, 360);
      const glm::vec3 right = pixel(layout, place, {w, 0.0f, 0.0f}, 640, 360);
      const glm::vec3 top = pixel(layout, place, head_points().top, 640, 360);
      const glm::vec3 chin = pixel(layout, place, head_points().chin, 640, 360);
      EXPECT_LT(left.x, right.x) << "facing the viewer";
      EXPECT_GE(left.x, 0.0f) << others << " " << left.x << " " << right.x;
      EXPECT_LE(right.x, 640.0f) << others;
      EXPECT_GE(top.y, 0.0f) << others;
      EXPECT_LE(chin.y, 360.0f) << others;
      EXPECT_GT(left.x, right_of_last) << "heads side by side without overlap: " << others;
      right_of_last = right.x;
    }
  }
}

TEST(FirstPersonLayout, FacesAreFrontalToThreeQuarterAndNoneIsInTheSelfView) {
  for (int others = 1; others <= 6; ++others) {
    const FirstPersonLayout layout = first_person_layout(others, 640, 360);
    for (const glm::mat4& place : layout.places) {
      const glm::vec3 forward = glm::normalize(glm::vec3(place * glm::vec4(0, 0, 1, 0)));
      const glm::vec3 to_camera = glm::normalize(layout.camera.position - glm::vec3(place[3]));
      EXPECT_GT(glm::dot(forward, to_camera), std::cos(50.0f * 0.0174533f)) << others;
      const glm::vec3 chin = pixel(layout, place, head_points().chin, 640, 360);
      EXPECT_FALSE(layout.self_tile.contains(static_cast<int>(chin.x), static_cast<int>(chin.y) + 12))
          << "a face's chin and name stay clear of the self view: " << others;
    }
  }
}

TEST(FirstPersonLayout, TheSelfViewFaceFillsItsTileInFrontOfEveryone) {
  const FirstPersonLayout layout = first_person_layout(4, 640, 360);
  const PixelRect tile = layout.self_tile;
  EXPECT_GE(tile.height, 100);
  EXPECT_LE(tile.x + tile.width, 640);
  EXPECT_LE(tile.y + tile.height, 360);
  const glm::vec3 top = pixel(layout, layout.self_place, head_points().top, 640, 360);
  const glm::vec3 chin = pixel(layout, layout.self_place, head_points().chin, 640, 360);
  EXPECT_TRUE(tile.contains(static_cast<int>(top.x), static_cast<int>(top.y)));
  EXPECT_TRUE(tile.contains(static_cast<int>(chin.x), static_cast<int>(chin.y)));
  EXPECT_GT(chin.y - top.y, 0.5f * static_cast<float>(tile.height));
  EXPECT_LT(glm::length(glm::vec3(layout.self_place[3]) - layout.camera.position),
            0.5f * glm::length(glm::vec3(layout.places[0][3]) - layout.camera.position))
      << "near the camera: in front of the others in depth";
}

TEST(FirstPersonLayout, OthersGoLeftToRightAsTheySitAtTheTableSeenFromTheViewer) {
  // Four seats on the server's arc, the viewer (2) second; facing yaw is minus
  // the seat's angle on the arc: the seats with smaller facing yaw lie to the
  // viewer's left.
  std::vector<SeatedAvatar> seated;
  const float facing[] = {1.3f, 0.44f, -0.44f, -1.3f};
  for (std::uint32_t id = 1; id <= 4; ++id) {
    codec::SeatInfo seat;
    seat.facing_yaw_rad = facing[id - 1];
    seated.push_back({id, seat});
  }
  EXPECT_EQ(others_left_to_right(seated, 2), (std::vector<std::uint32_t>{4, 3, 1}));
  // Without seats (all at the origin): by id.
  for (auto& s : seated) s.seat = {};
  EXPECT_EQ(others_left_to_right(seated, 3), (std::vector<std::uint32_t>{1, 2, 4}));
}

}  // namespace
}  // namespace fw::client
