#pragma once
// What a script means once parsed: keyframed action-unit animations, action
// unit definitions by control-point displacements, and vascular (blushing,
// pallor) expressions and emotion episodes. Plain data, filled by the
// semantic routines; the server prints it as JSON.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/script/diagnostic.hpp"

namespace fw::script {

/// One action unit of a keyframe.
struct AuIntensity {
  int au = 0;                 ///< FACS number
  double intensity = 0;       ///< as written, in [0, kMaxAuIntensity]: the paper's scale, 2 is the action unit at full strength
  /// The face's weight (FaceParams, 0 to 1): intensity / 2, the scale of the
  /// built-in expressions (avatar/model expressions.cpp, whose anger is the
  /// paper's halved), so a script and `express` at the same strength agree.
  double face_intensity = 0;
  bool carried = true;        ///< false: FaceParams has no channel for this action unit, it moves nothing
  SourcePosition position;
};

/// A full pose: every action unit not listed is at 0.
struct Keyframe {
  std::vector<AuIntensity> aus;
  SourcePosition position;
};

enum class PlayKind : unsigned char { animate, hold };

/// `Animate N "Shading"` (interpolate through the keyframes so far in N
/// steps) or `Hold N` (stay on the last keyframe for N steps).
struct Play {
  PlayKind kind = PlayKind::animate;
  int steps = 0;
  std::string shading;             ///< animate only: "Texture", "SmoothShading"... as written
  std::size_t keyframe_count = 0;  ///< keyframes written before this statement
  SourcePosition position;
};

/// One expression sentence: ClearAllFrame|KeepAllFrame, keyframes, plays, end.
struct KeyframeAnimation {
  bool clear_frames = true;  ///< ClearAllFrame: start from the neutral face; KeepAllFrame: continue from the current frames
  std::vector<Keyframe> keyframes;
  std::vector<Play> plays;
  SourcePosition position;
};

/// One control point of an AU definition and how far it moves at intensity 1.
struct ControlPointDisplacement {
  std::string region;                     ///< as written (facewire's or the paper's name)
  std::vector<std::string> face_regions;  ///< the generic face's regions it stands for
  int point = 0;                          ///< control-point index within the region
  std::array<double, 3> displacement{};   ///< dx, dy, dz in the units of the face model the definition was written for
  SourcePosition position;
};

/// `AU n / region point dx dy dz ... / true / Animate ... / end`.
struct AuDefinition {
  int au = 0;
  bool carried = true;  ///< false: FaceParams has no channel for this action unit
  std::vector<ControlPointDisplacement> displacements;
  bool preview_from_neutral = true;  ///< `true` (or nothing) / `false` before the previews
  std::vector<Play> previews;
  SourcePosition position;
};

/// Colour channels a vascular expression drives: FaceParams::blush regions
/// in kColourRegionNames order, then FaceParams::pallor.
inline constexpr std::size_t kColourChannelCount = codec::kColourRegionCount + 1;
inline constexpr std::size_t kPallorChannel = codec::kColourRegionCount;
using ColourChannels = std::array<double, kColourChannelCount>;

/// `[mpca REGION intensity X]` of a vascular expression.
struct RegionIntensity {
  std::string region;                 ///< as written: forehead, cheeks, ears, nose, head...
  std::vector<std::string> channels;  ///< the colour channels it drives
  double intensity = 0;               ///< [0, 1]
  SourcePosition position;
};

/// `[expression NAME [mpca ...] ...]`.
struct VascularExpression {
  std::string name;
  std::vector<RegionIntensity> regions;
  ColourChannels channels{};  ///< per channel, the largest intensity of the regions that drive it
  SourcePosition position;
};

/// `[stageN duration D [expression NAME intensity X]]`: during the stage the
/// colour moves from where the previous stage left it to the expression at
/// intensity X; a stage without an expression releases to 0.
struct EmotionStage {
  std::string name;
  double duration_percent = 0;  ///< of the whole episode
  double start_percent = 0;
  double end_percent = 0;
  std::string expression;  ///< empty: none
  double intensity = 0;    ///< [0, 1]
  SourcePosition position;
};

struct EnvelopeKey {
  double at_percent = 0;
  double intensity = 0;
};

struct ColourKey {
  double at_percent = 0;
  ColourChannels channels{};
};

/// `[emotion NAME [stage...] ...]`: an episode, in percent of its length.
struct VascularEmotion {
  std::string name;
  std::vector<EmotionStage> stages;
  std::vector<EnvelopeKey> envelope;   ///< intensity at 0% and at the end of every stage
  std::vector<ColourKey> colour_keys;  ///< the same keys as colours; empty unless colours_resolved
  bool colours_resolved = false;       ///< every expression it uses is defined in the script
  SourcePosition position;
};

struct ScriptMeaning {
  std::vector<KeyframeAnimation> animations;
  std::vector<AuDefinition> au_definitions;
  std::vector<VascularExpression> vascular_expressions;
  std::vector<VascularEmotion> emotions;
};

}  // namespace fw::script
