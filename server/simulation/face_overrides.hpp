#pragma once
// What a face-lab page holds on its preview avatar (PROTOCOL.md 5.16): each
// emotion's intensity, action units per side, head and eye angles, lid
// closure, blush per colour region and pallor, and whether the avatar's own
// behaviour runs. They hold until changed, so the preview shows exactly what
// the sliders say, through the same physics face a room's avatar has.
//
// Values from outside are clamped to FaceParams' ranges (a slider a little
// past its end is no error); what cannot mean anything (an emotion, action
// unit or colour region that does not exist, one side of a midline action
// unit) is refused with what to send instead. Not thread-safe: the room's
// strand.
#include <array>
#include <optional>
#include <string>

#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"

namespace fw::server {

/// Ranges the overrides are clamped to: FaceParams' own (face_params.hpp).
inline constexpr float kMaxHeadYawRad = 1.2f, kMaxHeadPitchRad = 0.8f, kMaxHeadRollRad = 0.6f;
inline constexpr float kMaxEyeYawRad = 0.6f, kMaxEyePitchRad = 0.5f;
/// The six primaries of avatar/behavior's emotion space, in wire order.
inline constexpr std::size_t kOverrideEmotions = 6;
/// The physics face's muscles (avatar/physics facial_muscles.hpp, its index
/// order: muscle i of the person's left side 2i, its right twin 2i + 1).
inline constexpr std::size_t kOverrideMuscles = 42;

struct FaceOverrides {
  /// The avatar's own behaviour (gaze, blinks, moods, expressions) runs
  /// under the overrides; off, the face is neutral but for them.
  bool behaviour = false;
  std::array<float, kOverrideEmotions> emotions{};  ///< joy .. disgust, 0 .. 1
  /// An action unit's channel set here replaces what emotions and behaviour give it.
  std::array<std::optional<float>, codec::kAuChannelCount> au{};
  std::optional<float> head_yaw, head_pitch, head_roll, eye_yaw, eye_pitch, lid_left, lid_right, pallor;
  std::array<std::optional<float>, codec::kColourRegionCount> blush{};
  /// The physics level: each muscle's least activation, 0 .. 1, on top of
  /// (the larger of it and) what the action units give the muscle.
  std::array<float, kOverrideMuscles> muscles{};
  /// The skin's age and looseness, 0 .. 1 (physics::TissueMaterial::aged).
  float skin_age = 0, skin_looseness = 0;
  /// Whether a muscle is driven: the preview's physics face then never sleeps.
  bool any_muscle() const;
};

using AuTargetArray = std::array<float, codec::kAuChannelCount>;

/// Sets one override, its value clamped; "" when done, else what was wrong
/// and what to send instead (the override is then left as it was).
std::string set_override(FaceOverrides& overrides, const codec::FaceOverride& change);

/// The preview's face for this tick, before the physics face: `face` is
/// what its behaviour made (kept only while behaviour is on; off, the face
/// starts neutral, with `played`, the action units of a FACS sentence being
/// played, if any, and with `face`'s own colour while `scripted_colour`: a
/// vascular emotion a script started is under way); the overrides are laid
/// over it.
void apply_overrides(const FaceOverrides& overrides, codec::FaceParams& face, const AuTargetArray* played,
                     bool scripted_colour = false);

}  // namespace fw::server
