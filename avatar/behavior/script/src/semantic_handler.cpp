#include "fw/script/semantic_handler.hpp"

#include <cassert>

namespace fw::script {

SemanticHandler::SemanticHandler(const Language& language, ScriptBuilder& script, DiagnosticList& diagnostics)
    : language_(language), script_(script), diagnostics_(diagnostics) {}

void SemanticHandler::begin_sentence() {
  values_.clear();
  script_.begin_sentence();
  errors_before_sentence_ = diagnostics_.error_count();
}

SemanticHandler::Expansion SemanticHandler::expand(int production, bool wanted, SourcePosition at) {
  const auto p = static_cast<std::size_t>(production);
  if (language_.routines[p]) return {true, true};
  const Production& prod = language_.grammar.productions[p];
  // A lone symbol hands its value straight up: no marker, so chains such as
  // <AUID> ::= IntLit cost nothing on the stack.
  if (prod.rhs.size() == 1 && language_.gives(prod.rhs[0])) return {false, wanted};
  // Anything else without a routine gives nothing; its children's values
  // would have no reader, so they are not kept. This is also why a list
  // written as <LIST> ::= <ITEM> <LIST> does not grow the stack.
  if (wanted) values_.push_back(SemanticValue::nothing(at));
  return {false, false};
}

void SemanticHandler::shift(const Token& token, bool wanted) {
  if (wanted) values_.push_back(token.value);
}

void SemanticHandler::complete(int production, bool wanted, SourcePosition at) {
  const auto p = static_cast<std::size_t>(production);
  const auto slots = static_cast<std::size_t>(language_.value_slots[p]);
  const Routine& routine = *language_.routines[p];
  assert(values_.size() >= slots && "every symbol that gives a value pushed one");
  if (values_.size() < slots) {
    diagnostics_.error(at, "internal error: routine " + routine.name + " is missing values");
    values_.clear();
    return;
  }
  const std::size_t base = values_.size() - slots;
  RoutineCall call{std::span<const SemanticValue>(values_.data() + base, slots), at, script_, diagnostics_};
  SemanticValue result = routine.run(call);
  values_.resize(base);
  if (wanted) {
    if (result.kind == ValueKind::none) result.position = at;
    values_.push_back(std::move(result));
  }
}

void SemanticHandler::end_sentence(bool parsed, SourcePosition start) {
  values_.clear();
  if (!parsed || diagnostics_.error_count() > errors_before_sentence_) {
    script_.discard_sentence();
    return;
  }
  if (const std::string open = script_.unfinished(); !open.empty()) {
    diagnostics_.warning(start, open);
    script_.discard_sentence();
  }
}

void SemanticHandler::finish() {
  for (FinishFunction run : language_.finishes) run(script_, diagnostics_);
}

}  // namespace fw::script
