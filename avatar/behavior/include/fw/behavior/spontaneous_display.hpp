#pragma once
// What an engaged face shows of its own accord: a display with a cause, not
// a uniform draw over the primaries.
//
// The cause is what the face feels: its own mood (moved by what it wrote)
// and the room's (moved by everyone's chat; behavior_room.cpp). A feeling
// clearly away from neutral is shown, at a strength that follows it. With
// nothing felt, the only display is the social one people make when they
// face each other: a mild smile (Kraut & Johnston 1979, "Social and
// emotional messages of smiling", J. Personality and Social Psychology 37:
// smiles go with facing others far more than with feeling happy). So a room
// whose chat is neutral or friendly shows no anger, disgust, fear or
// sadness without a cause.
#include <optional>
#include <random>

#include "fw/behavior/emotion_space.hpp"
#include "fw/behavior/expression_envelope.hpp"

namespace fw::behavior {

struct Display {
  Primary primary;
  ExpressionEnvelope envelope;
};

/// A felt coordinate must exceed the observers' neutral radius to be shown.
inline constexpr float kFeltToShow = kNeutralRadius;
/// A social smile's strength: mild (a "polite" smile, well under a laugh).
inline constexpr float kSocialSmileMin = 0.2f, kSocialSmileMax = 0.45f;
/// Seconds between displays: a face in conversation smiles now and then,
/// not every few seconds (a design choice within "rare and mild"; the
/// room tests measure the outcome).
inline constexpr double kDisplayIntervalMinS = 6.0, kDisplayIntervalMaxS = 16.0;

/// The display for `felt` (a point of expression space), with `rng` for
/// strength and timing. Always a display: the caller decides when.
Display spontaneous_display(const EmotionPoint& felt, std::mt19937_64& rng);

/// Seconds until the next display may start.
double next_display_after_s(std::mt19937_64& rng);

}  // namespace fw::behavior
