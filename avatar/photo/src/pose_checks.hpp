#pragma once
// Whether a found face can make a good avatar: big enough, whole, facing
// the camera (turned at most 35 degrees, tipped neither far back nor far
// down), eyes open. Any roll is accepted. Each refusal says what to change.
#include <optional>

#include <opencv2/core.hpp>

#include "face_alignment.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// Largest head turn (yaw) accepted, degrees: past it the far cheek is
/// hidden behind the nose and the texture has nothing there to show.
inline constexpr float kMaxYawDeg = 35.0f;
/// Largest head tilt (pitch) accepted, degrees: past it the forehead or the
/// chin hides much of the face.
inline constexpr float kMaxPitchDeg = 35.0f;

/// Estimated head yaw in degrees from the nose tip's offset between the two
/// ends of the jaw line (model frame), + toward the person's left.
float estimate_yaw_deg(const ModelLandmarks& landmarks);

/// nullopt if the face is usable, else the reason. `pitch_deg` is the head
/// pose fit's (+ tilted back, the chin raised).
std::optional<PrepError> check_face(const cv::Rect& box, const PhotoLandmarks& photo_landmarks, cv::Size photo_size,
                                    const ModelLandmarks& landmarks, float pitch_deg);

}  // namespace fw::photo
