#pragma once
// Semantic routines of vascular emotions and expressions in the bracket form
// of the vascular-expressions paper (section 5):
//   [emotion blushing [stage1 duration 10 [expression blush1 intensity 0.9]] ... [stage4 duration 20]]
//   [expression blush1 [mpca forehead intensity 0.4] [mpca cheeks intensity 0.6] ...]
#include "fw/script/routine_library.hpp"

namespace fw::script {

/// Adds to `library`:
/// - begin_emotion(name: text); begin_stage(name: text, duration: number):
///   a stage lasting `duration` percent of the episode (0 < d <= 100);
///   stage_expression(expression: text, intensity: number in [0, 1]): the
///   colour the stage ends on; end_emotion(): the durations must add up to
///   100; the intensity envelope is computed here;
/// - begin_vascular_expression(name: text); mpca_intensity(region: text,
///   intensity: number in [0, 1]): the region is checked with
///   colour_channels_for() (region_names.hpp), each once;
///   end_vascular_expression();
/// - a finishing step that, after the last sentence, turns every emotion's
///   stages into colour keys using the expressions defined anywhere in the
///   script, with a warning for each expression it cannot find.
void add_vascular_routines(RoutineLibrary& library);

}  // namespace fw::script
