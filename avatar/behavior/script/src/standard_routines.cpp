#include "fw/script/standard_routines.hpp"

#include "fw/script/au_definition_routines.hpp"
#include "fw/script/expression_routines.hpp"
#include "fw/script/vascular_routines.hpp"

namespace fw::script {

RoutineLibrary standard_routines() {
  RoutineLibrary library;
  add_expression_routines(library);
  add_au_definition_routines(library);
  add_vascular_routines(library);
  return library;
}

}  // namespace fw::script
