#include "fw/behavior/seat_layout.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(SeatLayout, ArcFacingItsCentreWithEvenSpacing) {
  const std::vector<Seat> seats = seat_layout(3);
  ASSERT_EQ(seats.size(), 3u);
  EXPECT_NEAR(glm::length(seats[0].origin_mm - seats[1].origin_mm), kSeatSpacingMm, 0.01f);
  EXPECT_NEAR(seats[1].origin_mm.x, 0, 1e-4f);
  EXPECT_NEAR(seats[1].facing_yaw_rad, 0, 1e-6f);
  // The seat on the viewer's right turns to the viewer's left (its right).
  EXPECT_GT(seats[2].origin_mm.x, 0);
  EXPECT_LT(seats[2].facing_yaw_rad, 0);
  // Every seat faces the same centre.
  for (const Seat& s : seats) {
    const glm::vec3 ahead = seat_to_room(s, {0, 0, 1}) - s.origin_mm;
    EXPECT_NEAR(glm::length(ahead), 1, 1e-5f);
  }
  EXPECT_EQ(seat_layout(1).size(), 1u);
  EXPECT_EQ(seat_layout(1)[0].facing_yaw_rad, 0);
  EXPECT_TRUE(seat_layout(0).empty());
}

TEST(SeatLayout, RoomAndSeatFramesAreInverse) {
  const Seat s = seat_layout(4)[3];
  const glm::vec3 p(12, -40, 300);
  const glm::vec3 back = room_to_seat(s, seat_to_room(s, p));
  EXPECT_NEAR(glm::length(back - p), 0, 1e-3f);
}

TEST(SeatLayout, GazeAnglesTowardAnotherSeatAreGeometric) {
  // From the middle seat of three, the neighbour on the viewer's right lies
  // toward the middle face's left (positive yaw), by 90 degrees less half
  // the arc between them (the chord's angle to the radius).
  const std::vector<Seat> seats = seat_layout(3);
  const glm::vec3 other = room_to_seat(seats[1], seats[2].origin_mm);
  const YawPitch a = direction_angles(other);
  EXPECT_NEAR(a.yaw_rad, 1.5707963f - 0.5f * kSeatAngleRad, 1e-3f);
}

TEST(SeatLayout, HeadTurnsAboutTheNeckPivot) {
  const HeadGeometry& g = head_geometry();
  EXPECT_GT(g.interocular_mm, 50);
  EXPECT_LT(g.interocular_mm, 75);
  EXPECT_LT(g.mouth_mm.y, g.eye_mid_mm.y);
  HeadPose turned;
  turned.yaw_rad = 0.5f;
  const glm::vec3 eyes = head_to_seat(turned, g.eye_mid_mm);
  EXPECT_GT(eyes.x, 0);  // turning toward the person's left moves the eyes to +x
  EXPECT_NEAR(glm::length(head_to_seat(turned, g.neck_pivot_mm) - g.neck_pivot_mm), 0, 1e-3f);
  const YawPitch a = direction_angles(direction_from_angles({0.3f, -0.2f}));
  EXPECT_NEAR(a.yaw_rad, 0.3f, 1e-5f);
  EXPECT_NEAR(a.pitch_rad, -0.2f, 1e-5f);
}

}  // namespace
}  // namespace fw::behavior
