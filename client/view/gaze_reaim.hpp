#pragma once
// Re-aiming a face in the first-person view (PROTOCOL.md 6.1). The server
// aims every face's eyes and head at the seat of whom it attends; this view
// puts the faces elsewhere, so each face is turned by the difference between
// where its target lies in the view and where it lay at the server, and the
// decoded motion around the server's aim (saccades, drift, tremor, the
// head's own sway) stays on top. Pure: angles and points in, angles out.
#include <chrono>
#include <cstdint>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"
#include "head_points.hpp"

namespace fw::client {

/// Radians added to a face's head, to its gaze (head plus eyes), and to
/// each eye's turn inward (vergence: a nearer target, more).
struct GazeCorrection {
  float head_yaw_rad = 0, head_pitch_rad = 0;
  float gaze_yaw_rad = 0, gaze_pitch_rad = 0;
  float half_vergence_rad = 0;
};

/// In the view the head turns at most this far from facing the viewer
/// (three-quarter); the eyes take what lies beyond.
inline constexpr float kViewHeadYawLimitRad = 0.87f;  // 50 degrees

/// A face attends a target: it stands at `server_place` at the server and at
/// `view_place` here; the target's eyes are at `server_target` and at
/// `view_target`. The gaze turns from the one direction to the other, and
/// the head with it, keeping the server's split between head and eyes (at
/// most kViewHeadYawLimitRad from the viewer; the eyes take the rest). For
/// `eye_contact` the head turns fully onto the viewer instead, so that the
/// irises sit centred in the eye openings: a face attending you holds its
/// head on you (its eyes keep their fine motion). The eyes converge on the
/// target at its distance in the view (never more than at the server).
GazeCorrection correction_toward(const codec::FaceParams& params, const glm::mat4& server_place,
                                 glm::vec3 server_target, const glm::mat4& view_place, glm::vec3 view_target,
                                 bool eye_contact);

/// A face that attends the room or nobody: head and gaze turn together by
/// the face's change of facing toward the viewer only (the viewer's eyes at
/// `server_viewer` at the server, `view_viewer` here), so a face searching the
/// room looks around as before and does not stare out of the screen.
GazeCorrection correction_of_facing(const codec::FaceParams& params, const glm::mat4& server_place,
                                    glm::vec3 server_viewer, const glm::mat4& view_place, glm::vec3 view_viewer);

/// `params` with the correction: head turned (kept in FaceParams' range and
/// within kViewHeadYawLimitRad), the eyes taking the rest of the gaze within
/// their range, vergence kept.
codec::FaceParams apply_correction(const codec::FaceParams& params, const GazeCorrection& correction);

/// Blends a face's correction over kBlendSeconds when its attention target
/// changes: the server's head moves smoothly to a new target, so the
/// correction must not jump when the attention message arrives.
class GazeBlend {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr double kBlendSeconds = 0.3;
  /// The correction to use now for a face whose target is `target` and whose
  /// correction for that target is `wanted`.
  GazeCorrection update(const codec::Attention::Entry& target, const GazeCorrection& wanted, Clock::time_point now);

 private:
  bool started_ = false;
  codec::AttentionTarget kind_ = codec::AttentionTarget::room;
  std::uint32_t target_avatar_ = 0;
  GazeCorrection from_{}, last_{};
  Clock::time_point since_{};
};

}  // namespace fw::client
