#include "fw/behavior/perception.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

std::vector<FaceSnapshot> room_of(int n) {
  std::vector<FaceSnapshot> room;
  const std::vector<Seat> seats = seat_layout(n);
  for (int i = 0; i < n; ++i) {
    FaceSnapshot s;
    s.id = static_cast<FaceId>(10 + i);
    s.seat = seats[static_cast<std::size_t>(i)];
    s.eye_mid_room_mm = seat_to_room(s.seat, head_geometry().eye_mid_mm);
    s.mouth_room_mm = seat_to_room(s.seat, head_geometry().mouth_mm);
    s.gaze_direction_room = glm::normalize(seat_to_room(s.seat, {0, 0, 1}) - s.seat.origin_mm);
    room.push_back(s);
  }
  return room;
}

TEST(Perception, SeesTheOthersWithTheirStateNotItself) {
  std::vector<FaceSnapshot> room = room_of(3);
  room[2].emotion = {0, 0, 0.9f, 0, 0, 0};
  room[2].emotion_template = classify(room[2].emotion);
  room[2].looking_at = 10;
  const std::vector<PerceivedFace> seen = perceive(room[0], room);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].id, 11u);  // nearest first
  EXPECT_EQ(seen[1].id, 12u);
  EXPECT_TRUE(seen[1].looks_at_me);
  EXPECT_EQ(label(seen[1].emotion_template), "anger");
  EXPECT_GT(seen[1].direction.yaw_rad, 0);  // on the viewer's right = the face's left
  EXPECT_LT(seen[1].mouth_seat_mm.y, seen[1].eyes_seat_mm.y);
}

TEST(Perception, OnlyWithinTheFieldOfView) {
  std::vector<FaceSnapshot> room = room_of(3);
  // Turned far to its right, away from the others: its seat is turned 60
  // degrees toward them (seat_layout), so the head turns 80 degrees more
  // to put the nearest 110 degrees off its gaze, past the 100-degree field.
  room[0].head_yaw_rad = -1.4f;
  EXPECT_TRUE(perceive(room[0], room).empty());
}

TEST(Perception, WhoLooksAtWhom) {
  std::vector<FaceSnapshot> room = room_of(3);
  const glm::vec3 from = room[0].eye_mid_room_mm;
  const glm::vec3 dir = glm::normalize(room[2].eye_mid_room_mm - from);
  EXPECT_EQ(face_on_gaze(10, from, dir, room), 12u);
  EXPECT_FALSE(face_on_gaze(10, from, glm::vec3(0, 1, 0), room));
  room[0].looking_at = 12;
  room[1].looking_at = 12;
  EXPECT_EQ(attending_count(12, room), 2);
  EXPECT_EQ(attending_count(10, room), 0);
}

TEST(Perception, GazeOnANearFacesCheekRestsOnThatFace) {
  // Two faces 250 mm apart, eye to eye: the other's cheek, 40 mm beside its
  // nose, is 9 degrees off its eyes and mouth (beyond the 8 degree cone)
  // yet on the face, as an eye tracker's face area counts it.
  FaceSnapshot other;
  other.id = 2;
  other.eye_mid_room_mm = {0, 0, 250};
  other.mouth_room_mm = {0, -70, 250};
  const glm::vec3 cheek{40, -35, 250};
  EXPECT_EQ(face_on_gaze(1, {0, 0, 0}, glm::normalize(cheek), {other}), std::optional<FaceId>(2));
  // A metre away a gaze 200 mm beside the face is off it.
  other.eye_mid_room_mm.z = other.mouth_room_mm.z = 1000;
  EXPECT_EQ(face_on_gaze(1, {0, 0, 0}, glm::normalize(glm::vec3{200, -35, 1000}), {other}), std::nullopt);
}

}  // namespace
}  // namespace fw::behavior
