#pragma once
// What the semantic routines say about where and how a grammar used them.
#include <string>

#include "fw/script/routine_library.hpp"

namespace fw::script {

/// "line:column", for messages that point back at an earlier place.
inline std::string at_text(SourcePosition p) { return std::to_string(p.line) + ":" + std::to_string(p.column); }

/// A routine that ran where it makes no sense: reached only through a
/// grammar that binds routines in the wrong places, so the message is for
/// its designer.
inline void misbound(RoutineCall& call, const char* routine, const char* needs) {
  call.diagnostics.error(call.position, std::string("the routine ") + routine + " ran outside " + needs +
                                            "; the grammar binds it to the wrong production");
}

}  // namespace fw::script
