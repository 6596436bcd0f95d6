#include "view_plan.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "head_points.hpp"

namespace fw::client {
namespace {

// Three seats of the server's arc (1 m radius, 50 degrees apart), the
// viewer (2) in the middle; each face looks straight ahead from its seat.
RoomScene three_seated(std::chrono::steady_clock::time_point now) {
  RoomScene scene;
  scene.you = 2;
  scene.now = now;
  for (std::uint32_t id = 1; id <= 3; ++id) {
    const float phi = (static_cast<float>(id) - 2.0f) * 0.8727f;
    SceneMember m;
    m.id = id;
    m.name = "n" + std::to_string(id);
    m.seat = {1000.0f * std::sin(phi), 0.0f, 1000.0f - 1000.0f * std::cos(phi), -phi};
    m.face = codec::FaceParams{};
    m.attention = {id, codec::AttentionTarget::room, 0};
    scene.members.push_back(m);
  }
  return scene;
}

float gaze_yaw(const codec::FaceParams& p) { return p.head_yaw_rad + 0.5f * (p.eye_left.yaw_rad + p.eye_right.yaw_rad); }

TEST(ViewPlan, TheOthersSitInTheirSeatOrderAndFacesWithoutFramesWait) {
  const auto now = std::chrono::steady_clock::now();
  RoomScene scene = three_seated(now);
  std::map<std::uint32_t, GazeBlend> blends;
  ViewPlan plan = plan_view(scene, 640, 360, blends);
  ASSERT_EQ(plan.others.size(), 2u);
  EXPECT_EQ(plan.others[0].id, 3u) << "the seat at the larger arc angle is on the viewer's left";
  EXPECT_EQ(plan.others[1].id, 1u);
  EXPECT_EQ(plan.others[0].name, "n3");
  scene.members[0].face.reset();
  plan = plan_view(scene, 640, 360, blends);
  ASSERT_EQ(plan.others.size(), 1u);
  EXPECT_EQ(blends.count(1), 0u) << "the blend of a face no longer shown is dropped";
}

TEST(ViewPlan, WithoutSeatsTheFacesAreShownAsDecoded) {
  RoomScene scene = three_seated(std::chrono::steady_clock::now());
  for (SceneMember& m : scene.members) {
    m.seat = {};
    m.face->head_yaw_rad = 0.2f;
  }
  scene.members[0].attention = {1, codec::AttentionTarget::avatar, 2};
  std::map<std::uint32_t, GazeBlend> blends;
  for (const PlacedFace& face : plan_view(scene, 640, 360, blends).others) EXPECT_FLOAT_EQ(face.params.head_yaw_rad, 0.2f);
}

TEST(ViewPlan, AFaceTurningToTheViewerDoesSoSmoothly) {
  const auto t0 = std::chrono::steady_clock::now();
  RoomScene scene = three_seated(t0);
  std::map<std::uint32_t, GazeBlend> blends;
  const float searching = gaze_yaw(plan_view(scene, 640, 360, blends).others[1].params);
  // The attention message arrives: avatar 1 now attends the viewer (and the
  // server's head has not moved yet).
  scene.members[0].attention = {1, codec::AttentionTarget::avatar, 2};
  const float at_once = gaze_yaw(plan_view(scene, 640, 360, blends).others[1].params);
  EXPECT_NEAR(at_once, searching, 1e-4f) << "no jump when the message arrives";
  // Meanwhile the server turned the face to the viewer's seat.
  SceneMember& face_1 = scene.members[0];
  const glm::mat4 seat = seat_place(face_1.seat.x_mm, face_1.seat.y_mm, face_1.seat.z_mm, face_1.seat.facing_yaw_rad);
  const glm::vec3 viewer = eyes_at(seat_place(0, 0, 0, 0), {});
  for (int i = 0; i < 3; ++i) {
    const YawPitch aim = angles_at(seat, viewer - eyes_at(seat, *face_1.face));
    face_1.face->head_yaw_rad = aim.yaw_rad - 0.1f;
    face_1.face->eye_left.yaw_rad = face_1.face->eye_right.yaw_rad = 0.1f;
  }
  scene.now = t0 + std::chrono::milliseconds(400);
  const ViewPlan later = plan_view(scene, 640, 360, blends);
  const PlacedFace& face = later.others[1];
  const YawPitch to_camera = angles_at(face.place, viewer_eyes(later.layout) - eyes_at(face.place, face.params));
  EXPECT_NEAR(gaze_yaw(face.params), to_camera.yaw_rad, 0.0175f) << "then it looks at the viewer";
  EXPECT_NEAR(face.params.head_yaw_rad, to_camera.yaw_rad, 0.0175f);
}

}  // namespace
}  // namespace fw::client
