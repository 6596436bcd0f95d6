// The client works out where the server aimed each face from the seats on
// the wire and its own copy of the head's geometry: both must be the
// server's (behavior's), or re-aimed faces would look past their targets.
#include "head_points.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "fw/behavior/seat_layout.hpp"
#include "fw/model/landmark_template.hpp"

namespace fw::client {
namespace {

TEST(HeadPoints, TheEyesAreWhereBehaviorPutsThemForAnyPoseAndSeat) {
  const auto seats = behavior::seat_layout(5);
  codec::FaceParams p;
  p.head_yaw_rad = 0.4f, p.head_pitch_rad = -0.2f, p.head_roll_rad = 0.1f;
  p.head_translation_mm = {5.0f, -3.0f, 8.0f};
  for (const behavior::Seat& seat : seats) {
    behavior::HeadPose pose{p.head_yaw_rad, p.head_pitch_rad, p.head_roll_rad, {5.0f, -3.0f, 8.0f}};
    const glm::vec3 expected_mm =
        behavior::seat_to_room(seat, behavior::head_to_seat(pose, behavior::head_geometry().eye_mid_mm));
    const glm::vec3 got = eyes_at(seat_place(seat.origin_mm.x, seat.origin_mm.y, seat.origin_mm.z, seat.facing_yaw_rad), p) *
                          model::kMillimetresPerUnit;
    EXPECT_NEAR(got.x, expected_mm.x, 0.05f);
    EXPECT_NEAR(got.y, expected_mm.y, 0.05f);
    EXPECT_NEAR(got.z, expected_mm.z, 0.05f);
  }
}

TEST(HeadPoints, DirectionsHaveBehaviorsSigns) {
  const behavior::Seat seat = behavior::seat_layout(3)[0];
  const glm::mat4 place = seat_place(seat.origin_mm.x, seat.origin_mm.y, seat.origin_mm.z, seat.facing_yaw_rad);
  for (const glm::vec3 d : {glm::vec3(1, 0.2f, 1), glm::vec3(-1, -0.3f, 0.5f), glm::vec3(0.2f, 0, -1)}) {
    const behavior::YawPitch expected = behavior::direction_angles(behavior::room_to_seat(seat, seat.origin_mm + d));
    const YawPitch got = angles_at(place, d);
    EXPECT_NEAR(got.yaw_rad, expected.yaw_rad, 1e-4f);
    EXPECT_NEAR(got.pitch_rad, expected.pitch_rad, 1e-4f);
  }
}

}  // namespace
}  // namespace fw::client
