#pragma once
// The routine library the shipped grammars are written against.
#include "fw/script/routine_library.hpp"

namespace fw::script {

/// Every routine of expression_routines.hpp, au_definition_routines.hpp and
/// vascular_routines.hpp, with their finishing steps.
RoutineLibrary standard_routines();

}  // namespace fw::script
