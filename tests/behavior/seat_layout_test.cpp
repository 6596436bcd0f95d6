#include "fw/behavior/seat_layout.hpp"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

constexpr float kOneDegreeRad = 0.017453293f;

TEST(SeatLayout, ArcWithEvenSpacingEachSeatTurnedTowardItsPartners) {
  const std::vector<Seat> seats = seat_layout(3);
  ASSERT_EQ(seats.size(), 3u);
  EXPECT_NEAR(glm::length(seats[0].origin_mm - seats[1].origin_mm), kSeatSpacingMm, 0.01f);
  EXPECT_NEAR(glm::length(seats[1].origin_mm - seats[2].origin_mm), kSeatSpacingMm, 0.01f);
  EXPECT_NEAR(seats[1].origin_mm.x, 0, 1e-4f);
  // The middle seat has a partner on each side: it faces the viewer.
  EXPECT_NEAR(seats[1].facing_yaw_rad, 0, 1e-6f);
  // The seat on the viewer's right turns to the viewer's left (its right),
  // toward the others, as far as the viewer still sees its face.
  EXPECT_GT(seats[2].origin_mm.x, 0);
  EXPECT_NEAR(seats[2].facing_yaw_rad, -kMaxFacingFromViewerRad, 1e-5f);
  EXPECT_NEAR(seats[0].facing_yaw_rad, kMaxFacingFromViewerRad, 1e-5f);
  EXPECT_EQ(seat_layout(1).size(), 1u);
  EXPECT_EQ(seat_layout(1)[0].facing_yaw_rad, 0);
  EXPECT_TRUE(seat_layout(0).empty());
}

// Old (every seat facing the arc's centre) against new (turned toward the
// partners within 60 degrees of the viewer), for every room size the server
// allows; the table in avatar/behavior/README.md is this output.
TEST(SeatLayout, PartnersWithinReachAndEveryFaceReadableForEveryRoomSize) {
  std::printf("seats | largest head yaw to a partner, old -> new | mean | largest face angle from the viewer\n");
  for (int n = 2; n <= 16; ++n) {
    const std::vector<Seat> seats = seat_layout(n);
    const SeatLayoutAngles now = seat_layout_angles(seats);
    const SeatLayoutAngles before = seat_layout_angles(centre_facing_arc_layout(n));
    std::printf("%5d | %3.0f -> %3.0f | %3.0f -> %3.0f | %3.0f -> %3.0f\n", n, before.largest_partner_yaw_rad / kOneDegreeRad,
                now.largest_partner_yaw_rad / kOneDegreeRad, before.mean_partner_yaw_rad / kOneDegreeRad,
                now.mean_partner_yaw_rad / kOneDegreeRad, before.largest_from_viewer_rad / kOneDegreeRad,
                now.largest_from_viewer_rad / kOneDegreeRad);
    SCOPED_TRACE(n);
    // Every face at rest within 60 degrees of the viewer.
    EXPECT_LE(now.largest_from_viewer_rad, kMaxFacingFromViewerRad + 1e-5f);
    // No partner farther from a seat's rest than a seat with neighbours on
    // both sides must turn for them (90 degrees less half the arc between
    // neighbours): the seats at the ends, turned toward the rest, do better.
    const float step = kSeatArcSpanRad / static_cast<float>(n - 1);
    EXPECT_LE(now.largest_partner_yaw_rad, 1.5707963f - 0.5f * step + 1e-4f);
    // Within the perceived half field (perception.hpp, 100 degrees): at
    // rest every face sees every other.
    EXPECT_LT(now.largest_partner_yaw_rad, 90 * kOneDegreeRad);
    // The viewer sees far more of every face than the centre-facing arc
    // showed of its end seats (past 60 degrees from four seats up).
    if (n >= 4) {
      EXPECT_GT(before.largest_from_viewer_rad, now.largest_from_viewer_rad + 14 * kOneDegreeRad);
    }
    // Facings never rise from the viewer's left to right (clients order by seat).
    for (std::size_t i = 1; i < seats.size(); ++i) EXPECT_LE(seats[i].facing_yaw_rad, seats[i - 1].facing_yaw_rad);
  }
  // A pair turns toward each other until the viewer would lose their faces:
  // 30 degrees of head turn instead of 65.
  EXPECT_NEAR(seat_layout_angles(seat_layout(2)).largest_partner_yaw_rad, 30 * kOneDegreeRad, 0.01f);
  EXPECT_NEAR(seat_layout_angles(centre_facing_arc_layout(2)).largest_partner_yaw_rad, 65 * kOneDegreeRad, 0.01f);
}

// 120 degrees is the spread that keeps the largest head turn smallest under
// the 60-degree limit: a flatter arc puts neighbours further to the side, a
// deeper one makes the end seats turn back past the limit.
TEST(SeatLayout, TheSpreadIsTheOneWithTheSmallestLargestHeadTurn) {
  for (int n = 3; n <= 16; ++n) {
    SCOPED_TRACE(n);
    const float chosen = seat_layout_angles(seat_layout(n)).largest_partner_yaw_rad;
    for (const float other_deg : {60.0f, 90.0f, 105.0f, 135.0f, 150.0f, 180.0f})
      EXPECT_LE(chosen, seat_layout_angles(seat_layout(n, other_deg * kOneDegreeRad)).largest_partner_yaw_rad + 1e-4f)
          << other_deg;
  }
}

TEST(SeatLayout, TheOldArcFacesItsCentre) {
  const std::vector<Seat> seats = centre_facing_arc_layout(4);
  EXPECT_NEAR(glm::length(seats[0].origin_mm - seats[1].origin_mm), kCentreFacingArcSpacingMm, 0.01f);
  EXPECT_NEAR(seats[3].facing_yaw_rad, -1.5f * kSeatAngleRad, 1e-5f);
  const glm::vec3 centre(0, 0, 0.5f * kCentreFacingArcSpacingMm / std::sin(0.5f * kSeatAngleRad));
  for (const Seat& s : seats) {
    const glm::vec3 ahead = glm::normalize(room_to_seat(s, centre));
    EXPECT_NEAR(ahead.z, 1, 1e-5f);
  }
}

TEST(SeatLayout, RoomAndSeatFramesAreInverse) {
  const Seat s = seat_layout(4)[3];
  const glm::vec3 p(12, -40, 300);
  const glm::vec3 back = room_to_seat(s, seat_to_room(s, p));
  EXPECT_NEAR(glm::length(back - p), 0, 1e-3f);
}

TEST(SeatLayout, GazeAnglesTowardAnotherSeatAreGeometric) {
  // From the middle seat of three (facing the viewer, the arc's centre), the
  // neighbour on the viewer's right lies toward the middle face's left
  // (positive yaw), by 90 degrees less half the arc between them (the
  // chord's angle to the radius).
  const std::vector<Seat> seats = seat_layout(3);
  const glm::vec3 other = room_to_seat(seats[1], seats[2].origin_mm);
  const YawPitch a = direction_angles(other);
  EXPECT_NEAR(a.yaw_rad, 1.5707963f - 0.25f * kSeatArcSpanRad, 1e-3f);
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
