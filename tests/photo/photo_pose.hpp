#pragma once
// What the photo tests that look at an avatar as the photo's camera saw it
// share: dlib's 68 points, and the head pose the photo showed.
#include <array>

#include <glm/vec2.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/photo/prepare_avatar.hpp"

namespace fw::photo::test_pose {

using Landmarks = std::array<glm::vec2, model::kLandmarkCount>;
inline constexpr float kRadiansPerDegree = 3.14159265f / 180.0f;

/// The neutral face turned and tilted as the photo's head was: a similarity
/// cannot undo a turn or a tilt, so a frontal render of a photo taken from a
/// little above would differ from it by the pose, not by the person.
inline codec::FaceParams as_photographed(const PrepReport& report) {
  codec::FaceParams params;
  params.head_yaw_rad = report.head_yaw_deg * kRadiansPerDegree;
  params.head_pitch_rad = report.head_pitch_deg * kRadiansPerDegree;
  return params;
}

}  // namespace fw::photo::test_pose
