#pragma once
// Helpers shared by the script tests: reading files of the source tree and
// building languages from grammar text.
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/language.hpp"
#include "fw/script/parser.hpp"
#include "fw/script/standard_routines.hpp"
#include "test_paths.hpp"

namespace fw::script::test {

using fw::test::source_path;

inline std::string read_source(const std::string& relative) {
  std::ifstream in(source_path(relative), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The language of `grammar_text` with the standard routines; nullopt and
/// `errors` when it does not load.
inline std::optional<Language> language_from(const std::string& grammar_text, std::vector<GrammarError>& errors,
                                             const std::string& name = "test.grammar") {
  return load_language({name, grammar_text}, builtin_resolver(), standard_routines(), errors);
}

/// Every message of `errors`, one a line, for failure output.
inline std::string joined(const std::vector<GrammarError>& errors) {
  std::string out;
  for (const GrammarError& e : errors) out += format_grammar_error(e) + "\n";
  return out;
}

inline std::string joined(const std::vector<Diagnostic>& diagnostics) {
  std::string out;
  for (const Diagnostic& d : diagnostics) out += format_diagnostic("script", d) + "\n";
  return out;
}

inline std::vector<Diagnostic> errors_of(const ScriptResult& result) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == Severity::error) out.push_back(d);
  return out;
}

inline std::vector<Diagnostic> warnings_of(const ScriptResult& result) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == Severity::warning) out.push_back(d);
  return out;
}

}  // namespace fw::script::test
