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

// Seats on an arc of `span_rad` open toward +z, 420 mm apart, the first
// at the viewer's left of the room (-x), each with the given facing.
std::vector<SeatedAvatar> seated_on_arc(float span_rad, const std::vector<float>& facings) {
  const int n = static_cast<int>(facings.size());
  const float step = span_rad / static_cast<float>(n - 1), radius = 210.0f / std::sin(0.5f * step);
  std::vector<SeatedAvatar> seated;
  for (int i = 0; i < n; ++i) {
    const float phi = (static_cast<float>(i) - 0.5f * static_cast<float>(n - 1)) * step;
    codec::SeatInfo seat;
    seat.x_mm = radius * std::sin(phi);
    seat.z_mm = radius * (1.0f - std::cos(phi));
    seat.facing_yaw_rad = facings[static_cast<std::size_t>(i)];
    seated.push_back({static_cast<std::uint32_t>(i + 1), seat});
  }
  return seated;
}

TEST(FirstPersonLayout, OthersGoLeftToRightAsTheySitAtTheTableSeenFromTheViewer) {
  // Four seats on the server's arc, the viewer (2) second. Seen from a seat,
  // the seats further toward the room's +x lie to the left, whatever the
  // facings: the server turns the end seats toward the others, alike when
  // the viewer's limit holds them (avatar/behavior seat_layout).
  EXPECT_EQ(others_left_to_right(seated_on_arc(2.094f, {1.047f, 0.0f, 0.0f, -1.047f}), 2),
            (std::vector<std::uint32_t>{4, 3, 1}));
  EXPECT_EQ(others_left_to_right(seated_on_arc(2.094f, {1.047f, 1.047f, -1.047f, -1.047f}), 2),
            (std::vector<std::uint32_t>{4, 3, 1}));
  // The centre-facing arc of earlier servers, over 270 degrees, where the
  // seats' x alone would not order them (the ends curl back toward +z).
  EXPECT_EQ(others_left_to_right(seated_on_arc(4.712f, {2.36f, 1.57f, 0.79f, 0.0f, -0.79f, -1.57f, -2.36f}), 4),
            (std::vector<std::uint32_t>{7, 6, 5, 3, 2, 1}));
  // Without seats (all at the origin): by id.
  std::vector<SeatedAvatar> seated = seated_on_arc(2.094f, {0.0f, 0.0f, 0.0f, 0.0f});
  for (auto& s : seated) s.seat = {};
  EXPECT_EQ(others_left_to_right(seated, 3), (std::vector<std::uint32_t>{1, 2, 4}));
}

}  // namespace
}  // namespace fw::client
