#include "gaze_reaim.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "first_person_layout.hpp"
#include "head_points.hpp"

namespace fw::client {
namespace {

constexpr float kDegree = 0.0174533f;

// Three seats as the server lays them out (an arc facing its centre 1 m
// away): a face at `server_f` attends whoever sits at `server_t`.
glm::mat4 server_seat(float phi) {
  const float r = 1000.0f;
  return seat_place(r * std::sin(phi), 0.0f, r - r * std::cos(phi), -phi);
}

// A face aiming at `target` as a server's would once settled: gaze on the
// target, the head carrying most of it, the eyes the rest.
codec::FaceParams aimed_at(const glm::mat4& place, glm::vec3 target) {
  codec::FaceParams p;
  YawPitch aim = angles_at(place, target - eyes_at(place, p));
  for (int i = 0; i < 5; ++i) {  // the eyes move as the head turns: settle
    p.head_yaw_rad = 0.8f * aim.yaw_rad;
    p.head_pitch_rad = 0.5f * aim.pitch_rad;
    aim = angles_at(place, target - eyes_at(place, p));
    p.eye_left = p.eye_right = {aim.yaw_rad - p.head_yaw_rad, aim.pitch_rad - p.head_pitch_rad};
  }
  // Both eyes turned in on the target.
  const float half_vergence = std::atan(0.5f * head_points().interocular / glm::length(target - eyes_at(place, p)));
  p.eye_left.yaw_rad -= half_vergence;
  p.eye_right.yaw_rad += half_vergence;
  return p;
}

YawPitch gaze(const codec::FaceParams& p) {
  return {p.head_yaw_rad + 0.5f * (p.eye_left.yaw_rad + p.eye_right.yaw_rad),
          p.head_pitch_rad + 0.5f * (p.eye_left.pitch_rad + p.eye_right.pitch_rad)};
}

struct Room {
  glm::mat4 f_server = server_seat(-0.8727f);  // the face, at the arc's left end
  glm::mat4 viewer_server = server_seat(0.0f);
  glm::mat4 t_server = server_seat(0.8727f);
  FirstPersonLayout layout = first_person_layout(2, 640, 360);
  glm::mat4 f_view = layout.places[1];
  glm::mat4 t_view = layout.places[0];
  glm::vec3 viewer_eyes_server = eyes_at(viewer_server, {});
};

TEST(GazeReaim, AFaceAttendingTheViewerLooksIntoTheCameraWithItsHeadTurnedToIt) {
  const Room room;
  const codec::FaceParams p = aimed_at(room.f_server, room.viewer_eyes_server);
  const GazeCorrection c = correction_toward(p, room.f_server, room.viewer_eyes_server, room.f_view,
                                             viewer_eyes(room.layout), true);
  const codec::FaceParams out = apply_correction(p, c);
  const YawPitch want = angles_at(room.f_view, viewer_eyes(room.layout) - eyes_at(room.f_view, out));
  EXPECT_NEAR(gaze(out).yaw_rad, want.yaw_rad, kDegree);
  EXPECT_NEAR(gaze(out).pitch_rad, want.pitch_rad, kDegree);
  EXPECT_NEAR(out.head_yaw_rad, want.yaw_rad, kDegree) << "the head turned fully: the irises sit centred";
  EXPECT_NEAR(0.5f * (out.eye_left.yaw_rad + out.eye_right.yaw_rad), 0.0f, kDegree);
  EXPECT_NEAR(out.eye_right.pitch_rad, 0.0f, kDegree);
  // Both eyes converge on the viewer's eyes, 1.3 m away: a degree or so each.
  const float half_vergence = std::atan(0.5f * head_points().interocular / glm::length(viewer_eyes(room.layout) - eyes_at(room.f_view, out)));
  EXPECT_NEAR(out.eye_left.yaw_rad, -half_vergence, 1e-3f);
  EXPECT_NEAR(out.eye_right.yaw_rad, half_vergence, 1e-3f);
}

TEST(GazeReaim, TheDecodedFineMotionSurvivesAsTheSameOffset) {
  const Room room;
  codec::FaceParams p = aimed_at(room.f_server, room.viewer_eyes_server);
  const GazeCorrection c = correction_toward(p, room.f_server, room.viewer_eyes_server, room.f_view,
                                             viewer_eyes(room.layout), true);
  const codec::FaceParams still = apply_correction(p, c);
  // A saccade's worth of offset on top of the aim.
  p.eye_left.yaw_rad += 0.05f, p.eye_right.yaw_rad += 0.05f;
  p.eye_left.pitch_rad -= 0.03f, p.eye_right.pitch_rad -= 0.03f;
  const codec::FaceParams moved = apply_correction(p, c);
  EXPECT_NEAR(gaze(moved).yaw_rad - gaze(still).yaw_rad, 0.05f, 1e-4f);
  EXPECT_NEAR(gaze(moved).pitch_rad - gaze(still).pitch_rad, -0.03f, 1e-4f);
  EXPECT_FLOAT_EQ(moved.head_yaw_rad, still.head_yaw_rad) << "a face attending the viewer holds its head on the viewer";
  // A face searching the room keeps its head's sway too.
  codec::FaceParams q;
  q.head_yaw_rad = 0.5f;
  const GazeCorrection ct = correction_of_facing(q, room.f_server, room.viewer_eyes_server, room.f_view, viewer_eyes(room.layout));
  const codec::FaceParams q_still = apply_correction(q, ct);
  q.head_yaw_rad += 0.02f;
  const codec::FaceParams q_swayed = apply_correction(q, ct);
  EXPECT_NEAR(q_swayed.head_yaw_rad - q_still.head_yaw_rad, 0.02f, 1e-4f);
  // Vergence (the eyes turned in) is kept.
  p.eye_left.yaw_rad -= 0.01f, p.eye_right.yaw_rad += 0.01f;
  const codec::FaceParams verged = apply_correction(p, c);
  EXPECT_NEAR(verged.eye_right.yaw_rad - verged.eye_left.yaw_rad, moved.eye_right.yaw_rad - moved.eye_left.yaw_rad + 0.02f, 1e-4f);
}

TEST(GazeReaim, AFaceAttendingItsNeighbourLooksAtTheNeighboursPlaceInTheView) {
  const Room room;
  const glm::vec3 t_server_eyes = eyes_at(room.t_server, {});
  const codec::FaceParams p = aimed_at(room.f_server, t_server_eyes);
  const glm::vec3 t_view_eyes = eyes_at(room.t_view, {});
  const GazeCorrection c = correction_toward(p, room.f_server, t_server_eyes, room.f_view, t_view_eyes, false);
  const codec::FaceParams out = apply_correction(p, c);
  const YawPitch want = angles_at(room.f_view, t_view_eyes - eyes_at(room.f_view, out));
  // The neighbour sits on the viewer's left, the face's right: negative yaw,
  // far off to the side (two people side by side). The head stops at
  // three-quarter and the eyes take the rest (the eye nearer the neighbour
  // may reach the end of its range: within 2 degrees).
  EXPECT_LT(want.yaw_rad, -1.1f);
  EXPECT_NEAR(out.head_yaw_rad, -kViewHeadYawLimitRad, 1e-5f) << "the head turns toward the neighbour, to three-quarter";
  EXPECT_LT(0.5f * (out.eye_left.yaw_rad + out.eye_right.yaw_rad), -0.3f) << "the eyes take the rest";
  EXPECT_NEAR(gaze(out).yaw_rad, want.yaw_rad, 2.0f * kDegree);
  EXPECT_NEAR(gaze(out).pitch_rad, want.pitch_rad, kDegree);
}

TEST(GazeReaim, AFaceSearchingTheRoomTurnsOnlyByItsChangeOfFacing) {
  const Room room;
  codec::FaceParams p;  // looking straight ahead from its seat: the table's middle
  p.eye_left.yaw_rad = p.eye_right.yaw_rad = 0.1f;
  const GazeCorrection c = correction_of_facing(p, room.f_server, room.viewer_eyes_server, room.f_view,
                                                viewer_eyes(room.layout));
  EXPECT_FLOAT_EQ(c.head_yaw_rad, c.gaze_yaw_rad);
  const codec::FaceParams out = apply_correction(p, c);
  // At the server the viewer lay off to the face's left; looking at the
  // table's middle, the face looks past the viewer in the view too.
  const YawPitch server_viewer = angles_at(room.f_server, room.viewer_eyes_server - eyes_at(room.f_server, p));
  const YawPitch view_viewer = angles_at(room.f_view, viewer_eyes(room.layout) - eyes_at(room.f_view, out));
  EXPECT_NEAR(gaze(out).yaw_rad - view_viewer.yaw_rad, gaze(p).yaw_rad - server_viewer.yaw_rad,
              std::abs(out.head_yaw_rad) >= kViewHeadYawLimitRad - 1e-4f ? 0.2f : kDegree);
  EXPECT_GT(std::abs(gaze(out).yaw_rad - view_viewer.yaw_rad), 0.3f) << "not staring out of the screen";
}

TEST(GazeReaim, AChangeOfTargetIsBlendedOverAFewTenthsOfASecond) {
  GazeBlend blend;
  const auto t0 = std::chrono::steady_clock::time_point{} + std::chrono::hours(1);
  const codec::Attention::Entry viewer{5, codec::AttentionTarget::avatar, 2};
  const codec::Attention::Entry neighbour{5, codec::AttentionTarget::avatar, 3};
  const GazeCorrection a{0.2f, 0.0f, 0.4f, 0.0f, 0.0f}, b{-0.2f, 0.1f, -0.4f, 0.1f, 0.01f};
  EXPECT_FLOAT_EQ(blend.update(viewer, a, t0).gaze_yaw_rad, 0.4f) << "the first is taken as it is";
  EXPECT_FLOAT_EQ(blend.update(neighbour, b, t0).gaze_yaw_rad, 0.4f) << "no jump when the message arrives";
  const float half = blend.update(neighbour, b, t0 + std::chrono::milliseconds(150)).gaze_yaw_rad;
  EXPECT_GT(half, -0.3f);
  EXPECT_LT(half, 0.3f);
  EXPECT_FLOAT_EQ(blend.update(neighbour, b, t0 + std::chrono::milliseconds(300)).gaze_yaw_rad, -0.4f);
  EXPECT_FLOAT_EQ(blend.update(neighbour, a, t0 + std::chrono::milliseconds(310)).gaze_yaw_rad, 0.4f)
      << "the same target: the correction follows at once";
}

}  // namespace
}  // namespace fw::client
