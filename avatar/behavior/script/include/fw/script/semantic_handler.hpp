#pragma once
// The semantic handler: keeps the values that tokens and productions give,
// and calls the routine bound to a production once all of its symbols are
// recognised, handing it exactly the values it takes. The same handler
// serves every language; only the bindings differ.
#include <vector>

#include "fw/script/diagnostic.hpp"
#include "fw/script/language.hpp"
#include "fw/script/script_builder.hpp"
#include "fw/script/token.hpp"

namespace fw::script {

class SemanticHandler {
 public:
  /// All three must outlive the handler.
  SemanticHandler(const Language& language, ScriptBuilder& script, DiagnosticList& diagnostics);

  /// What the parser driver should do for a production it expands.
  struct Expansion {
    bool complete_later = false;   ///< push a marker and call complete() when its symbols are recognised
    bool children_wanted = false;  ///< its symbols' values are waited for (each that gives one)
  };

  void begin_sentence();
  /// The parser expands `production`; `wanted`: the parent waits for its value.
  Expansion expand(int production, bool wanted, SourcePosition at);
  /// The parser matched `token`; `wanted`: a routine waits for its value.
  void shift(const Token& token, bool wanted);
  /// Every symbol of `production` (which has a routine) has been recognised.
  void complete(int production, bool wanted, SourcePosition at);
  /// @param parsed  no syntax error in the sentence; with one, or with an
  ///                error from a routine, the sentence's meaning is dropped
  void end_sentence(bool parsed, SourcePosition start);
  /// Runs the library's finishing routines, once, after the last sentence.
  void finish();

 private:
  const Language& language_;
  ScriptBuilder& script_;
  DiagnosticList& diagnostics_;
  std::vector<SemanticValue> values_;
  std::size_t errors_before_sentence_ = 0;
};

}  // namespace fw::script
