#pragma once
// Semantic routines of expression sentences (the paper's
// `ClearAllFrame BeginKeyFrame 2 1.0 4 2.0 ... Animate 2 "Texture" end`).
#include "fw/script/routine_library.hpp"

namespace fw::script {

/// Adds to `library`:
/// - clear_all_frames(), keep_all_frames(): open an expression sentence that
///   starts from the neutral face, or continues from the current frames;
/// - begin_keyframe(): start a keyframe (a full pose: unlisted AUs are 0);
/// - au_intensity(au: integer, intensity: number): one action unit of the
///   keyframe; AU numbers must be FACS codes (facs.hpp), intensities lie in
///   [0, kMaxAuIntensity], the paper's scale: 2 is the action unit at its
///   full strength, the face's weight is half the written intensity; an AU
///   faces do not carry (e.g. 42) is kept with a warning;
/// - animate(steps: integer, shading: optional text): play through the
///   keyframes so far in `steps` steps (shading defaults to "Texture"); in an
///   AU definition, a preview;
/// - hold(steps: integer): stay on the last keyframe for `steps` steps;
/// - end_animation(): close the sentence into ScriptMeaning::animations.
void add_expression_routines(RoutineLibrary& library);

}  // namespace fw::script
