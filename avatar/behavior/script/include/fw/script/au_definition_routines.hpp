#pragma once
// Semantic routines of action-unit definitions (the paper's
// `AU 1 / Above_Brow 6 0.00 10.00 0.00 / ... / true / Animate 4 "Texture" / end`).
// The result is the parsed definition; applying it to the face's morphs is
// another module's work.
#include "fw/script/routine_library.hpp"

namespace fw::script {

/// Adds to `library`:
/// - begin_au_definition(au: integer): open the definition of a FACS action
///   unit (a warning when faces do not carry it);
/// - control_point_displacement(region: text, point: integer, dx, dy, dz:
///   numbers): how far one control point of a region moves at intensity 1;
///   the region is checked with face_regions_for() (region_names.hpp),
///   0 <= point <= kMaxControlPoint, |d| <= kMaxDisplacement, each
///   (region, point) once;
/// - start_from_neutral(), start_from_current(): the paper's `true` /
///   `false` before the previews: whether the preview starts from the
///   neutral face (the default) or from the current frames;
/// - end_au_definition(): close it into ScriptMeaning::au_definitions (an
///   action unit defined twice in one script is an error).
/// The previews use `animate` from expression_routines.hpp.
void add_au_definition_routines(RoutineLibrary& library);

}  // namespace fw::script
