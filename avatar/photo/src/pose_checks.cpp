#include "pose_checks.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "fw/photo/photo_limits.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

constexpr float kDegreesPerRadian = 180.0f / std::numbers::pi_v<float>;

std::string rounded(float v) { return std::to_string(static_cast<int>(std::lround(v))); }

float opening(const ModelLandmarks& l, int begin) {
  const auto at = [&](int i) { return l[static_cast<std::size_t>(begin + i)]; };
  const float height = 0.5f * (std::abs(at(1).y - at(5).y) + std::abs(at(2).y - at(4).y));
  const float width = std::abs(at(3).x - at(0).x);
  return width > 0 ? height / width : 0.0f;
}

}  // namespace

float estimate_yaw_deg(const ModelLandmarks& l) {
  // A turned head moves the nose tip (well in front of the neck) sideways
  // more than the ends of the jaw line (near the ears): offset/width = 0.655
  // tan(yaw) on the generic face's depth profile.
  const glm::vec2 right = l[lm::kJawBegin], left = l[lm::kJawEnd - 1], nose = l[lm::kNoseTip];
  const float width = left.x - right.x;
  if (width <= 0) return 90.0f;
  const float offset = (nose.x - 0.5f * (left.x + right.x)) / width;
  return std::atan(offset / 0.655f) * kDegreesPerRadian;
}

std::optional<PrepError> check_face(const cv::Rect& box, const PhotoLandmarks& photo_landmarks, cv::Size photo_size,
                                    const ModelLandmarks& landmarks, float pitch_deg) {
  // Face width from ear to ear along the jaw line: the detector's box is
  // tighter than the face and varies with the detector.
  const glm::vec2 jaw = photo_landmarks[lm::kJawEnd - 1] - photo_landmarks[lm::kJawBegin];
  const int face_width = static_cast<int>(std::lround(std::hypot(jaw.x, jaw.y)));
  if (face_width < kMinFaceWidthPx)
    return PrepError{PrepErrorCode::face_too_small, "the face is " + std::to_string(face_width) + " px wide; at least " +
                                                        std::to_string(kMinFaceWidthPx) +
                                                        " px is needed (100 or more is better): use a larger photo or one taken closer"};
  const cv::Rect image(0, 0, photo_size.width, photo_size.height);
  const cv::Rect inside = box & image;
  bool landmark_outside = false;
  for (const glm::vec2& p : photo_landmarks)
    landmark_outside |= p.x < 0 || p.y < 0 || p.x >= static_cast<float>(photo_size.width) || p.y >= static_cast<float>(photo_size.height);
  if (landmark_outside || inside.area() < 0.85 * box.area())
    return PrepError{PrepErrorCode::face_cut_off,
                     "the face is cut off by the edge of the photo; use one that shows the whole face with some space around it"};

  // No limit on roll: turning a photo is no reason to refuse it, and the
  // landmarks and the texture are both taken with the face turned upright.
  const float yaw = estimate_yaw_deg(landmarks);
  if (std::abs(yaw) > kMaxYawDeg)
    return PrepError{PrepErrorCode::head_turned, "the head is turned about " + rounded(std::abs(yaw)) +
                                                     " degrees; use a photo facing the camera (within about " +
                                                     rounded(kMaxYawDeg) + " degrees)"};
  if (std::abs(pitch_deg) > kMaxPitchDeg)
    return PrepError{PrepErrorCode::head_tilted, std::string("the head is tilted ") + (pitch_deg > 0 ? "back" : "down") +
                                                     " about " + rounded(std::abs(pitch_deg)) +
                                                     " degrees; use a photo with the face level with the camera (within "
                                                     "about " + rounded(kMaxPitchDeg) + " degrees)"};
  if (opening(landmarks, lm::kEyeRightBegin) < 0.1f || opening(landmarks, lm::kEyeLeftBegin) < 0.1f)
    return PrepError{PrepErrorCode::eyes_closed, "the eyes are closed or nearly closed; use a photo with open eyes"};
  return std::nullopt;
}

}  // namespace fw::photo
