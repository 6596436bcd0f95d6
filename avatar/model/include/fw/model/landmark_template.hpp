#pragma once
// The canonical 68-landmark face (iBUG 300-W / dlib point order) in the
// model frame every other part of facewire uses.
//
// Model frame: origin midway between the two eye centres, x toward the
// viewer's right (the person's left), y up, z toward the viewer. One unit is
// the inter-ocular distance (eye centre to eye centre, about 63 mm on an
// adult). "left" and "right" always mean the person's own sides.
#include <array>
#include <cstdint>
#include <span>

#include <glm/vec2.hpp>

namespace fw::model {

inline constexpr int kLandmarkCount = 68;
/// Millimetres per model unit when a face is given the adult mean inter-ocular distance.
inline constexpr float kMillimetresPerUnit = 63.0f;

/// Landmark index ranges (first, one past last) in the iBUG order.
namespace landmarks {
inline constexpr int kJawBegin = 0, kJawEnd = 17;            // person's right ear to left ear
inline constexpr int kBrowRightBegin = 17, kBrowRightEnd = 22;
inline constexpr int kBrowLeftBegin = 22, kBrowLeftEnd = 27;
inline constexpr int kNoseBridgeBegin = 27, kNoseBridgeEnd = 31;
inline constexpr int kNoseBaseBegin = 31, kNoseBaseEnd = 36;
inline constexpr int kEyeRightBegin = 36, kEyeRightEnd = 42;  // viewer's left
inline constexpr int kEyeLeftBegin = 42, kEyeLeftEnd = 48;    // viewer's right
inline constexpr int kOuterLipBegin = 48, kOuterLipEnd = 60;
inline constexpr int kInnerLipBegin = 60, kInnerLipEnd = 68;
inline constexpr int kChin = 8, kNoseTip = 30, kMouthCornerRight = 48, kMouthCornerLeft = 54;
}  // namespace landmarks

/// The 68 canonical landmark positions (x, y) in the model frame.
/// The mean shape of the 300-W training faces as dlib's 68-point predictor
/// stores it, made exactly left/right symmetric and rescaled to the model
/// frame, with the inner lips closed to a 1.5 % slit (a neutral face at rest
/// has its lips together; the photo fit moves them to where the person has them).
std::span<const glm::vec2, kLandmarkCount> landmark_template();

/// The landmark that mirrors landmark `i` across the face's vertical midline.
int mirrored_landmark(int i);

}  // namespace fw::model
