#include "gaze_reaim.hpp"

#include <algorithm>
#include <cmath>

namespace fw::client {
namespace {

// FaceParams' ranges (codec/face_params.hpp); the eyes a little less far
// sideways: in a head turned to three-quarter an eye turned further still
// leaves the socket beside the eyeball in view.
constexpr float kHeadYawRange = 1.2f, kHeadPitchRange = 0.8f;
constexpr float kEyeYawRange = 0.5f, kEyePitchRange = 0.5f;

// Gaze yaw and pitch of the cyclopean eye (FaceParams' signs, seat frame).
YawPitch gaze_of(const codec::FaceParams& p) {
  return {p.head_yaw_rad + 0.5f * (p.eye_left.yaw_rad + p.eye_right.yaw_rad),
          p.head_pitch_rad + 0.5f * (p.eye_left.pitch_rad + p.eye_right.pitch_rad)};
}

YawPitch aim_from(const codec::FaceParams& p, const glm::mat4& place, glm::vec3 target) {
  return angles_at(place, target - eyes_at(place, p));
}

// Angles wrapped into (-pi, pi], so that a turn never goes the long way round.
float wrapped(float a) { return std::remainder(a, 6.2831853f); }

float smoothstep(double s) {
  const double c = std::clamp(s, 0.0, 1.0);
  return static_cast<float>(c * c * (3 - 2 * c));
}

}  // namespace

GazeCorrection correction_toward(const codec::FaceParams& params, const glm::mat4& server_place,
                                 glm::vec3 server_target, const glm::mat4& view_place, glm::vec3 view_target,
                                 bool eye_contact) {
  const glm::vec3 server_eyes = eyes_at(server_place, params);
  const YawPitch server_aim = angles_at(server_place, server_target - server_eyes);
  // The eyes move with the head: the view's direction is taken from where
  // they are once the head has turned (a few rounds settle it).
  codec::FaceParams turned = params;
  GazeCorrection c;
  for (int round = 0; round < 3; ++round) {
    const YawPitch view_aim = aim_from(turned, view_place, view_target);
    c.gaze_yaw_rad = wrapped(view_aim.yaw_rad - server_aim.yaw_rad);
    c.gaze_pitch_rad = view_aim.pitch_rad - server_aim.pitch_rad;
    c.head_yaw_rad = eye_contact ? wrapped(view_aim.yaw_rad - params.head_yaw_rad) : c.gaze_yaw_rad;
    c.head_pitch_rad = eye_contact ? view_aim.pitch_rad - params.head_pitch_rad : c.gaze_pitch_rad;
    turned = apply_correction(params, c);
  }
  const auto half_vergence = [](float distance) {
    return std::atan(0.5f * head_points().interocular / std::max(distance, 0.5f));
  };
  // Less vergence for a farther target, never more than the server's: the
  // view seats heads side by side, closer than people sit.
  c.half_vergence_rad = std::min(0.0f, half_vergence(glm::length(view_target - eyes_at(view_place, turned))) -
                                           half_vergence(glm::length(server_target - server_eyes)));
  return c;
}

GazeCorrection correction_of_facing(const codec::FaceParams& params, const glm::mat4& server_place,
                                    glm::vec3 server_viewer, const glm::mat4& view_place, glm::vec3 view_viewer) {
  // The yaw only: a face looking at the table keeps looking at the table's
  // height wherever the viewer's eyes are.
  const float turn = wrapped(aim_from(params, view_place, view_viewer).yaw_rad -
                             aim_from(params, server_place, server_viewer).yaw_rad);
  return {turn, 0.0f, turn, 0.0f, 0.0f};
}

codec::FaceParams apply_correction(const codec::FaceParams& params, const GazeCorrection& c) {
  codec::FaceParams out = params;
  const YawPitch gaze = gaze_of(params);
  out.head_yaw_rad = std::clamp(params.head_yaw_rad + c.head_yaw_rad, -std::min(kHeadYawRange, kViewHeadYawLimitRad),
                                std::min(kHeadYawRange, kViewHeadYawLimitRad));
  out.head_pitch_rad = std::clamp(params.head_pitch_rad + c.head_pitch_rad, -kHeadPitchRange, kHeadPitchRange);
  const YawPitch eye{gaze.yaw_rad + c.gaze_yaw_rad - out.head_yaw_rad, gaze.pitch_rad + c.gaze_pitch_rad - out.head_pitch_rad};
  // Vergence (the eyes turned in on a near target) as decoded, for the
  // target's distance here.
  const float half_vergence_yaw = 0.5f * (params.eye_right.yaw_rad - params.eye_left.yaw_rad) + c.half_vergence_rad;
  const float half_vergence_pitch = 0.5f * (params.eye_right.pitch_rad - params.eye_left.pitch_rad);
  const auto eye_yaw = [](float y) { return std::clamp(y, -kEyeYawRange, kEyeYawRange); };
  const auto eye_pitch = [](float p) { return std::clamp(p, -kEyePitchRange, kEyePitchRange); };
  out.eye_left = {eye_yaw(eye.yaw_rad - half_vergence_yaw), eye_pitch(eye.pitch_rad - half_vergence_pitch)};
  out.eye_right = {eye_yaw(eye.yaw_rad + half_vergence_yaw), eye_pitch(eye.pitch_rad + half_vergence_pitch)};
  return out;
}

GazeCorrection GazeBlend::update(const codec::Attention::Entry& target, const GazeCorrection& wanted,
                                 Clock::time_point now) {
  const bool same = started_ && target.target == kind_ &&
                    (target.target != codec::AttentionTarget::avatar || target.target_avatar == target_avatar_);
  if (!same) {
    from_ = started_ ? last_ : wanted;  // the first correction is taken as it is
    since_ = now;
    started_ = true;
    kind_ = target.target;
    target_avatar_ = target.target_avatar;
  }
  const float s = smoothstep(std::chrono::duration<double>(now - since_).count() / kBlendSeconds);
  last_ = {from_.head_yaw_rad + (wanted.head_yaw_rad - from_.head_yaw_rad) * s,
           from_.head_pitch_rad + (wanted.head_pitch_rad - from_.head_pitch_rad) * s,
           from_.gaze_yaw_rad + (wanted.gaze_yaw_rad - from_.gaze_yaw_rad) * s,
           from_.gaze_pitch_rad + (wanted.gaze_pitch_rad - from_.gaze_pitch_rad) * s,
           from_.half_vergence_rad + (wanted.half_vergence_rad - from_.half_vergence_rad) * s};
  return last_;
}

}  // namespace fw::client
