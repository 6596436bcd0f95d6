#pragma once
// Reads grammar files in the paper's format (#Terminal, #Production, #End),
// extended with how each terminal is scanned, a #Scanner section, routine
// bindings (`=> routine`) and #Include. The format is described in this
// module's README.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fw/script/grammar.hpp"

namespace fw::script {

/// The text of one grammar file and the name it goes by in messages.
struct GrammarSource {
  std::string name;
  std::string text;
};

/// Finds the file that `#Include name` in `including_file` means; nullopt if
/// there is none.
using GrammarResolver =
    std::function<std::optional<GrammarSource>(const std::string& including_file, const std::string& name)>;

/// Reads `source` and everything it includes into one grammar, checking that
/// every symbol is declared or defined and that terminals can be told apart.
/// It does not check that the grammar is LL(1) (parse_table.hpp does).
/// @param[in]  source   the top grammar file; the first production written in
///                      it names the start symbol
/// @param[in]  resolve  finds included files; may be empty when nothing is included
/// @param[out] grammar  the grammar, complete only on success
/// @param[out] errors   every problem found, at most kMaxGrammarErrors
/// @return true when `errors` stayed empty
bool read_grammar(const GrammarSource& source, const GrammarResolver& resolve, Grammar& grammar,
                  std::vector<GrammarError>& errors);

}  // namespace fw::script
