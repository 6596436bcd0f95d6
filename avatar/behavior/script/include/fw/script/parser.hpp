#pragma once
// The parser driver: one fixed table-driven LL(1) loop that, with the
// scanner driver and the semantic handler, turns a script into its meaning
// for any language. A script is a sequence of sentences, each derived from
// the grammar's start symbol. After a syntax error the parser reports it
// (line, column, what was expected, what was found) and resumes at the next
// token that can start a sentence outside any bracket opened since the
// failed sentence began, so one run reports the errors of many sentences.
#include <cstddef>
#include <string_view>
#include <vector>

#include "fw/script/diagnostic.hpp"
#include "fw/script/language.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::script {

struct ScriptResult {
  ScriptMeaning meaning;                ///< the sentences without errors
  std::vector<Diagnostic> diagnostics;  ///< errors and warnings, in the order found
  std::size_t sentences = 0;            ///< sentences read, including those with errors

  bool ok() const {
    for (const Diagnostic& d : diagnostics)
      if (d.severity == Severity::error) return false;
    return true;
  }
};

/// Parses `text` (at most kMaxScriptBytes) in `language`. Never throws or
/// crashes on any input; time is linear in the input.
ScriptResult parse_script(const Language& language, std::string_view text);

}  // namespace fw::script
