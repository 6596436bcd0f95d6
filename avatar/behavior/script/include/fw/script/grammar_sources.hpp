#pragma once
// Where grammar text comes from: the grammars shipped in grammars/, compiled
// into the library so that no file has to sit beside a binary, and grammar
// files on disk, which change the language without a rebuild.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fw/script/grammar_reader.hpp"
#include "fw/script/language.hpp"

namespace fw::script {

/// The shipped grammars: expression.grammar, au_definition.grammar,
/// vascular.grammar, and facewire.grammar, which includes the three.
std::vector<std::string_view> builtin_grammar_names();
/// The shipped grammar called `name` (e.g. "expression.grammar"), named
/// "<builtin>/expression.grammar" in messages; nullopt if there is none.
std::optional<GrammarSource> builtin_grammar(std::string_view name);

/// Resolves #Include among the shipped grammars only.
GrammarResolver builtin_resolver();
/// Resolves #Include to a file in the including file's directory, or else to
/// a shipped grammar of that name; includes inside shipped grammars resolve
/// to shipped grammars only.
GrammarResolver file_resolver();

/// Reads a grammar file (at most kMaxGrammarBytes).
/// @return the source, or nullopt and `error` naming the file and the problem
std::optional<GrammarSource> read_grammar_file(const std::string& path, std::string& error);

/// The language of facewire.grammar with standard_routines(): expression
/// sentences, AU definitions and vascular emotions, in any order. Built on
/// first use; the shipped grammars are tested to load.
const Language& default_language();

}  // namespace fw::script
