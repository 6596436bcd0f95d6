#include "face_overrides.hpp"

#include <algorithm>
#include <cmath>

#include "fw/behavior/emotion_space.hpp"

namespace fw::server {
namespace {

using codec::AuSide;
using codec::OverridePart;

/// A wire value (ten-thousandths) clamped to [-limit, limit] or [0, limit].
float clamped(std::int16_t value, float low, float high) {
  return std::clamp(static_cast<float>(value) / 10000.0f, low, high);
}

std::string action_unit_list() {
  std::string list;
  for (const auto au : codec::kActionUnits) {
    if (!list.empty()) list += ' ';
    list += std::to_string(au);
  }
  return list;
}

std::string set_action_unit(FaceOverrides& o, const codec::FaceOverride& c) {
  const int au = c.index;
  if (std::find(codec::kActionUnits.begin(), codec::kActionUnits.end(), au) == codec::kActionUnits.end())
    return "action unit " + std::to_string(au) + " is not one the face shows; use one of " + action_unit_list();
  const auto side = static_cast<AuSide>(c.side);
  if (!codec::is_bilateral(au) && side != AuSide::both)
    return "action unit " + std::to_string(au) + " moves the middle of the face: set it on both sides (side 0)";
  const float value = clamped(c.value, 0, 1);
  if (!codec::is_bilateral(au)) {
    o.au[static_cast<std::size_t>(codec::au_channel(au, AuSide::both))] = value;
    return {};
  }
  for (const AuSide s : {AuSide::left, AuSide::right})
    if (side == AuSide::both || side == s) o.au[static_cast<std::size_t>(codec::au_channel(au, s))] = value;
  return {};
}

void set_lids(FaceOverrides& o, const codec::FaceOverride& c) {
  const float value = clamped(c.value, 0, 1);
  if (c.side != 2) o.lid_left = value;
  if (c.side != 1) o.lid_right = value;
}

/// `value` if set, else `otherwise`.
float or_else(const std::optional<float>& value, float otherwise) { return value ? *value : otherwise; }

}  // namespace

std::string set_override(FaceOverrides& o, const codec::FaceOverride& c) {
  switch (c.part) {
    case OverridePart::emotion:
      if (c.index >= kOverrideEmotions)
        return "emotion " + std::to_string(c.index) + " does not exist; use 0 joy, 1 sadness, 2 anger, 3 fear, "
                                                      "4 surprise, 5 disgust";
      o.emotions[c.index] = clamped(c.value, 0, 1);
      return {};
    case OverridePart::action_unit: return set_action_unit(o, c);
    case OverridePart::head_yaw: o.head_yaw = clamped(c.value, -kMaxHeadYawRad, kMaxHeadYawRad); return {};
    case OverridePart::head_pitch: o.head_pitch = clamped(c.value, -kMaxHeadPitchRad, kMaxHeadPitchRad); return {};
    case OverridePart::head_roll: o.head_roll = clamped(c.value, -kMaxHeadRollRad, kMaxHeadRollRad); return {};
    case OverridePart::eye_yaw: o.eye_yaw = clamped(c.value, -kMaxEyeYawRad, kMaxEyeYawRad); return {};
    case OverridePart::eye_pitch: o.eye_pitch = clamped(c.value, -kMaxEyePitchRad, kMaxEyePitchRad); return {};
    case OverridePart::lids: set_lids(o, c); return {};
    case OverridePart::blush:
      if (c.index >= codec::kColourRegionCount)
        return "colour region " + std::to_string(c.index) + " does not exist; use 0 forehead, 1 left cheek, "
                                                            "2 right cheek, 3 nose, 4 sides";
      o.blush[c.index] = clamped(c.value, 0, 1);
      return {};
    case OverridePart::pallor: o.pallor = clamped(c.value, 0, 1); return {};
    case OverridePart::behaviour: o.behaviour = c.value != 0; return {};
    case OverridePart::reset: o = FaceOverrides{}; return {};
    case OverridePart::muscle:
      if (c.index >= kOverrideMuscles)
        return "muscle " + std::to_string(c.index) + " does not exist; use 0 .. 41 (PROTOCOL.md 5.16 lists them: " +
               "even the person's left, odd the right)";
      if (c.side != 0) return "a muscle index names its side already: send side 0";
      o.muscles[c.index] = clamped(c.value, 0, 1);
      return {};
    case OverridePart::skin_age: o.skin_age = clamped(c.value, 0, 1); return {};
    case OverridePart::skin_looseness: o.skin_looseness = clamped(c.value, 0, 1); return {};
  }
  return "unknown override";  // the codec reads no other part
}

bool FaceOverrides::any_muscle() const {
  return std::any_of(muscles.begin(), muscles.end(), [](float a) { return a > 0.0f; });
}

void apply_overrides(const FaceOverrides& o, codec::FaceParams& face, const AuTargetArray* played,
                     bool scripted_colour) {
  if (!o.behaviour) {
    // Neutral, straight ahead, lids open, no colour: what is left is the
    // sliders' (and a FACS sentence or vascular emotion played meanwhile).
    const codec::FaceParams made = face;
    face = codec::FaceParams{};
    if (played) face.au = *played;
    if (scripted_colour) face.blush = made.blush, face.pallor = made.pallor;
  }
  behavior::EmotionPoint point{};
  std::copy(o.emotions.begin(), o.emotions.end(), point.begin());
  float emotion_lids = 0;
  const auto emotion_aus = behavior::emotion_action_units(point, &emotion_lids);
  for (std::size_t c = 0; c < face.au.size(); ++c)
    face.au[c] = or_else(o.au[c], std::max(face.au[c], emotion_aus[c]));
  face.head_yaw_rad = or_else(o.head_yaw, face.head_yaw_rad);
  face.head_pitch_rad = or_else(o.head_pitch, face.head_pitch_rad);
  face.head_roll_rad = or_else(o.head_roll, face.head_roll_rad);
  for (codec::EyeRotation* eye : {&face.eye_left, &face.eye_right}) {
    eye->yaw_rad = or_else(o.eye_yaw, eye->yaw_rad);
    eye->pitch_rad = or_else(o.eye_pitch, eye->pitch_rad);
  }
  face.lid_left = or_else(o.lid_left, std::max(face.lid_left, emotion_lids));
  face.lid_right = or_else(o.lid_right, std::max(face.lid_right, emotion_lids));
  for (std::size_t r = 0; r < face.blush.size(); ++r) face.blush[r] = or_else(o.blush[r], face.blush[r]);
  face.pallor = or_else(o.pallor, face.pallor);
}

}  // namespace fw::server
