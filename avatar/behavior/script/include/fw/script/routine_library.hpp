#pragma once
// The semantic routines a grammar can bind to its productions by name
// (`<AUHEAD> ::= <AUID> <STRENGTH> => au_intensity`), as in the paper's
// action routine library: a designer picks routines here, or registers new
// ones, without touching the drivers.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fw/script/diagnostic.hpp"
#include "fw/script/script_builder.hpp"
#include "fw/script/semantic_value.hpp"

namespace fw::script {

/// Which values a routine parameter takes.
inline constexpr ValueKinds kIntegerParameter = kinds_of(ValueKind::integer);
inline constexpr ValueKinds kNumberParameter = kinds_of(ValueKind::integer) | kinds_of(ValueKind::real);
inline constexpr ValueKinds kTextParameter = kinds_of(ValueKind::text);
/// Added to a parameter: the value may be missing (the production chose an
/// alternative that gives none).
inline constexpr ValueKinds kOptional = kinds_of(ValueKind::none);

struct RoutineParameter {
  ValueKinds accepts = 0;
  std::string meaning;  ///< for messages: "the action-unit number"
};

/// What a routine sees when the production it is bound to has been recognised.
struct RoutineCall {
  std::span<const SemanticValue> values;  ///< one per parameter, of the kinds the parameter accepts
  SourcePosition position;                ///< where the production's text starts
  ScriptBuilder& script;
  DiagnosticList& diagnostics;
};

/// Returns the value the production gives upward (usually nothing).
using RoutineFunction = SemanticValue (*)(RoutineCall& call);
/// Runs once after the last sentence, e.g. to resolve names used before
/// their definition.
using FinishFunction = void (*)(ScriptBuilder& script, DiagnosticList& diagnostics);

struct Routine {
  std::string name;
  /// What it takes, in order: the values the production's symbols give.
  /// Keywords and symbols give none; integers, reals, strings and names
  /// give theirs; a nonterminal gives what its production gives.
  std::vector<RoutineParameter> parameters;
  ValueKind result = ValueKind::none;
  RoutineFunction run = nullptr;
  std::string summary;  ///< one line for the designer
};

class RoutineLibrary {
 public:
  /// Adds `routine`. @return false if the library has one of that name already
  bool add(Routine routine);
  void add_finish(FinishFunction finish);
  /// The routine called `name`, or nullptr.
  const Routine* find(std::string_view name) const;
  const std::vector<Routine>& routines() const { return routines_; }
  const std::vector<FinishFunction>& finishes() const { return finishes_; }

 private:
  std::vector<Routine> routines_;
  std::vector<FinishFunction> finishes_;
};

/// "an integer", "a number", "a text or nothing"... for messages.
std::string describe_kinds(ValueKinds kinds);

}  // namespace fw::script
