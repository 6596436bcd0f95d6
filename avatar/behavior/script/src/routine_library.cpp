#include "fw/script/routine_library.hpp"

namespace fw::script {

bool RoutineLibrary::add(Routine routine) {
  if (find(routine.name)) return false;
  routines_.push_back(std::move(routine));
  return true;
}

void RoutineLibrary::add_finish(FinishFunction finish) { finishes_.push_back(finish); }

const Routine* RoutineLibrary::find(std::string_view name) const {
  for (const Routine& routine : routines_)
    if (routine.name == name) return &routine;
  return nullptr;
}

std::string describe_kinds(ValueKinds kinds) {
  std::string out;
  const auto add = [&](const char* what) { out += (out.empty() ? "" : " or ") + std::string(what); };
  if ((kinds & kNumberParameter) == kNumberParameter) add("a number");
  else if (kinds & kinds_of(ValueKind::integer)) add("an integer");
  else if (kinds & kinds_of(ValueKind::real)) add("a real number");
  if (kinds & kinds_of(ValueKind::text)) add("a text");
  if (kinds & kinds_of(ValueKind::none)) add("nothing");
  return out.empty() ? "nothing" : out;
}

}  // namespace fw::script
