#include "fw/script/au_definition_routines.hpp"

#include <cmath>

#include "fw/script/facs.hpp"
#include "fw/script/limits.hpp"
#include "fw/script/region_names.hpp"
#include "routine_messages.hpp"

namespace fw::script {
namespace {

AuDefinition* open_definition(RoutineCall& call, const char* routine) {
  if (call.script.au_definition) return &*call.script.au_definition;
  call.diagnostics.error(call.position, std::string("the routine ") + routine +
                                            " ran outside an AU definition (bind begin_au_definition first); the "
                                            "grammar binds it to the wrong production");
  return nullptr;
}

SemanticValue begin_au_definition(RoutineCall& call) {
  const SemanticValue& number = call.values[0];
  AuDefinition definition;
  definition.au = static_cast<int>(number.integer);
  definition.position = call.position;
  if (!is_facs_action_unit(number.integer)) {
    call.diagnostics.error(number.position, "AU " + std::to_string(number.integer) +
                                                " is not a FACS action unit (FACS numbers are " +
                                                std::string(facs_ranges_text()) + ")");
    definition.au = 0;
  } else if (!is_carried_by_faces(number.integer)) {
    definition.carried = false;
    call.diagnostics.warning(number.position,
                             "AU " + std::to_string(number.integer) + " (" +
                                 std::string(facs_action_unit_name(number.integer)) +
                                 ") is a FACS action unit that facewire's faces do not show (they show AUs " +
                                 carried_action_units_text() + "); its definition is kept but moves nothing");
  }
  call.script.au_definition = std::move(definition);
  return {};
}

SemanticValue control_point_displacement(RoutineCall& call) {
  AuDefinition* definition = open_definition(call, "control_point_displacement");
  if (!definition) return {};
  const SemanticValue& region = call.values[0];
  const SemanticValue& point = call.values[1];
  bool ok = true;
  ControlPointDisplacement d;
  d.region = region.text;
  d.face_regions = face_regions_for(region.text);
  d.position = region.position;
  if (d.face_regions.empty()) {
    call.diagnostics.error(region.position, "unknown region '" + printable(region.text) + "'; regions are " +
                                                face_region_names_text() + " (case does not matter)");
    ok = false;
  }
  if (point.integer < 0 || point.integer > kMaxControlPoint) {
    call.diagnostics.error(point.position, "control point " + std::to_string(point.integer) +
                                               " is out of range: write 0 to " + std::to_string(kMaxControlPoint));
    ok = false;
  }
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const SemanticValue& v = call.values[2 + axis];
    d.displacement[axis] = v.number();
    if (!(std::abs(d.displacement[axis]) <= kMaxDisplacement)) {
      call.diagnostics.error(v.position, "the displacement " + number_text(v.number()) + " is out of range: write -" +
                                             number_text(kMaxDisplacement) + " to " + number_text(kMaxDisplacement));
      ok = false;
    }
  }
  if (!ok) return {};
  d.point = static_cast<int>(point.integer);
  for (const ControlPointDisplacement& earlier : definition->displacements) {
    if (earlier.point != d.point || earlier.face_regions != d.face_regions) continue;
    call.diagnostics.error(region.position, "control point " + std::to_string(d.point) + " of " + d.region +
                                                " already moves at " + at_text(earlier.position) + "; give it once");
    return {};
  }
  if (definition->displacements.size() >= kMaxDisplacements) {
    call.diagnostics.error(region.position, "more than " + std::to_string(kMaxDisplacements) +
                                                " control points in one AU definition");
    return {};
  }
  definition->displacements.push_back(std::move(d));
  return {};
}

SemanticValue start_from_neutral(RoutineCall& call) {
  if (AuDefinition* definition = open_definition(call, "start_from_neutral")) definition->preview_from_neutral = true;
  return {};
}

SemanticValue start_from_current(RoutineCall& call) {
  if (AuDefinition* definition = open_definition(call, "start_from_current")) definition->preview_from_neutral = false;
  return {};
}

SemanticValue end_au_definition(RoutineCall& call) {
  AuDefinition* definition = open_definition(call, "end_au_definition");
  if (!definition) return {};
  for (const AuDefinition& earlier : call.script.meaning.au_definitions) {
    if (earlier.au != definition->au) continue;
    call.diagnostics.error(definition->position, "AU " + std::to_string(definition->au) +
                                                     " is already defined at " + at_text(earlier.position) +
                                                     "; keep one definition per script");
    return {};
  }
  call.script.meaning.au_definitions.push_back(std::move(*definition));
  call.script.au_definition.reset();
  return {};
}

}  // namespace

void add_au_definition_routines(RoutineLibrary& library) {
  library.add({"begin_au_definition", {{kIntegerParameter, "the action-unit number"}}, ValueKind::none,
               begin_au_definition, "opens the definition of an action unit"});
  library.add({"control_point_displacement",
               {{kTextParameter, "the region"},
                {kIntegerParameter, "the control point"},
                {kNumberParameter, "dx"},
                {kNumberParameter, "dy"},
                {kNumberParameter, "dz"}},
               ValueKind::none,
               control_point_displacement,
               "moves one control point of a region"});
  library.add({"start_from_neutral", {}, ValueKind::none, start_from_neutral,
               "previews the action unit from the neutral face"});
  library.add({"start_from_current", {}, ValueKind::none, start_from_current,
               "previews the action unit from the current frames"});
  library.add({"end_au_definition", {}, ValueKind::none, end_au_definition, "closes an AU definition"});
}

}  // namespace fw::script
