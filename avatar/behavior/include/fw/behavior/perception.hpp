#pragma once
// Perception through the room only ("Behavioral Animation of Faces", 4.1):
// a face senses the others through what the room shares each tick (where
// each head is, its eyes and mouth, where it looks, its emotion point and
// template), and only those within its field of view.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "fw/behavior/emotion_space.hpp"
#include "fw/behavior/seat_layout.hpp"

namespace fw::behavior {

using FaceId = std::uint32_t;

/// What the room shares about one face after a tick.
struct FaceSnapshot {
  FaceId id = 0;
  Seat seat;
  glm::vec3 eye_mid_room_mm{0.0f};
  glm::vec3 mouth_room_mm{0.0f};
  glm::vec3 gaze_direction_room{0.0f, 0.0f, 1.0f};  ///< unit vector from eye_mid
  float head_yaw_rad = 0;                           ///< relative to the seat's facing
  std::optional<FaceId> looking_at;                 ///< the face its gaze rests on
  EmotionPoint emotion{};
  EmotionTemplate emotion_template;
  std::optional<double> speaking_since_s;  ///< the room time its line began, while it speaks
};

/// A face another one perceives.
struct PerceivedFace {
  FaceId id = 0;
  glm::vec3 eyes_seat_mm{0.0f};   ///< its eyes, in the observer's seat frame
  glm::vec3 mouth_seat_mm{0.0f};
  YawPitch direction;             ///< from the observer's eyes, seat frame
  float distance_mm = 0;
  std::optional<FaceId> looking_at;
  bool looks_at_me = false;
  EmotionPoint emotion{};
  EmotionTemplate emotion_template;
  std::optional<double> speaking_since_s;  ///< heard: the room time its line began, while it speaks
};

/// Half the horizontal field of view, about the head's direction.
inline constexpr float kFieldOfViewHalfRad = 1.75f;  ///< 100 degrees
/// A gaze within this angle of a face's eyes rests on that face.
inline constexpr float kAttendConeRad = 0.14f;  ///< 8 degrees
/// A near face is larger than that cone: a gaze that passes within this
/// distance of the face's centre (between the eyes and the mouth) rests on
/// it too, as an eye tracker's face area of interest counts any fixation on
/// the face, eyes, nose or mouth (the face region of Rogers et al. 2018;
/// about the half-width of an adult face, 140-150 mm wide).
inline constexpr float kFaceAreaRadiusMm = 70.0f;

/// The faces `self` perceives in `room` (itself excluded), nearest first.
std::vector<PerceivedFace> perceive(const FaceSnapshot& self, const std::vector<FaceSnapshot>& room);

/// The face whose eyes or mouth lie nearest `gaze` (origin, unit direction)
/// within kAttendConeRad, or whose face area it crosses, if any; `self` is
/// never one.
std::optional<FaceId> face_on_gaze(FaceId self, glm::vec3 origin, glm::vec3 direction,
                                   const std::vector<FaceSnapshot>& room);

/// How many faces of `room` look at `id`.
int attending_count(FaceId id, const std::vector<FaceSnapshot>& room);

}  // namespace fw::behavior
