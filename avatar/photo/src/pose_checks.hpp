#pragma once
// Whether a found face can make a good avatar: big enough, whole, facing
// the camera, upright, eyes open. Each refusal says what to change.
#include <optional>

#include <opencv2/core.hpp>

#include "face_alignment.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// Largest head turn (yaw) and tilt (roll) accepted, degrees.
inline constexpr float kMaxYawDeg = 25.0f;
inline constexpr float kMaxRollDeg = 40.0f;

/// Estimated head yaw in degrees from the nose tip's offset between the two
/// ends of the jaw line (model frame), + toward the person's left.
float estimate_yaw_deg(const ModelLandmarks& landmarks);

/// nullopt if the face is usable, else the reason.
std::optional<PrepError> check_face(const cv::Rect& box, const PhotoLandmarks& photo_landmarks, cv::Size photo_size,
                                    const Alignment& alignment, const ModelLandmarks& landmarks);

}  // namespace fw::photo
