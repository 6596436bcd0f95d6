// The client's room places and the seats the server's behavior aims gaze
// at must agree, or avatars would look past one another on screen.
#include "room_layout.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "fw/behavior/seat_layout.hpp"
#include "fw/model/landmark_template.hpp"

namespace fw::client {
namespace {

TEST(RoomLayoutSeats, SmallRoomsSitExactlyWhereBehaviorSeatsThem) {
  // Up to three: larger rooms are narrowed to 120 degrees (room_layout.cpp).
  for (int count = 1; count <= 3; ++count) {
    const auto places = room_places(count);
    const auto seats = behavior::seat_layout(count);
    ASSERT_EQ(places.size(), seats.size());
    for (int i = 0; i < count; ++i) {
      const auto& seat = seats[static_cast<std::size_t>(i)];
      const glm::mat4 expected =
          glm::rotate(glm::translate(glm::mat4(1.0f), seat.origin_mm / model::kMillimetresPerUnit), seat.facing_yaw_rad,
                      glm::vec3(0.0f, 1.0f, 0.0f));
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          EXPECT_NEAR(places[static_cast<std::size_t>(i)][c][r], expected[c][r], 1e-4f) << count << " seats, seat " << i;
    }
  }
}

}  // namespace
}  // namespace fw::client
