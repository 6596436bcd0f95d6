#pragma once
// The expression space of "Behavioral Animation of Faces" (section 4.1): an
// emotional state is a point in the 6-D unit hypercube whose axes are the
// primary expressions (joy, sadness, anger, fear, surprise, disgust), neutral
// at the origin. Emotion templates partition the cube into regions an
// observer names; the faces perceive each other's point and template.
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "fw/codec/face_params.hpp"

namespace fw::behavior {

enum class Primary : std::uint8_t { joy, sadness, anger, fear, surprise, disgust, count };
inline constexpr std::size_t kPrimaryCount = static_cast<std::size_t>(Primary::count);
inline constexpr std::array<std::string_view, kPrimaryCount> kPrimaryNames = {
    "joy", "sadness", "anger", "fear", "surprise", "disgust"};

/// A point of expression space, each coordinate in [0, 1].
using EmotionPoint = std::array<float, kPrimaryCount>;

/// The observer's names for regions of expression space: neutral near the
/// origin, one primary where it dominates, and the blends observers name
/// (fearful surprise, angry disgust...) where two are close and strong.
struct EmotionTemplate {
  std::optional<Primary> first;   ///< none: neutral
  std::optional<Primary> second;  ///< a blend's weaker primary
  float intensity = 0;            ///< the dominant coordinate
  bool operator==(const EmotionTemplate&) const = default;
};

/// Below this every coordinate reads as neutral.
inline constexpr float kNeutralRadius = 0.15f;
/// A second primary within this ratio of the first makes a blend.
inline constexpr float kBlendRatio = 0.7f;

/// The template whose region holds `point`.
EmotionTemplate classify(const EmotionPoint& point);
/// "neutral", "joy", "fear+surprise"...
std::string label(const EmotionTemplate& t);

/// The primary named `name` ("joy"...), or nullopt; "neutral" is not a primary.
std::optional<Primary> primary_from_name(std::string_view name);

/// Every coordinate clamped to [0, 1].
EmotionPoint clamp_to_cube(EmotionPoint p);

/// Moves `point` toward neutral: each coordinate halves every `half_life_s`.
EmotionPoint decay_toward_neutral(const EmotionPoint& point, double dt_s, double half_life_s);

/// The action-unit targets that show `point` (FaceParams::au order): each
/// primary through fw::model's expression table at its coordinate, blended
/// by max as the table does. Lid closure of the expressions in `lid_closure`.
std::array<float, codec::kAuChannelCount> emotion_action_units(const EmotionPoint& point, float* lid_closure = nullptr);

}  // namespace fw::behavior
