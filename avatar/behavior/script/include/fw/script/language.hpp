#pragma once
// A language ready to run: the grammar with its scan table, its LL(1) parse
// table and its productions bound to routines. Building one is the whole of
// the language transducer generator; loading another grammar file gives
// another language for the same drivers, no rebuild needed.
#include <optional>
#include <vector>

#include "fw/script/grammar.hpp"
#include "fw/script/grammar_reader.hpp"
#include "fw/script/parse_table.hpp"
#include "fw/script/routine_library.hpp"
#include "fw/script/scan_table.hpp"

namespace fw::script {

struct Language {
  Grammar grammar;
  ScanTable scan;
  ParseTable parse;
  std::vector<std::optional<Routine>> routines;  ///< per production: the routine bound to it
  std::vector<int> value_slots;                  ///< per production: how many of its symbols give a value
  std::vector<bool> nonterminal_gives;           ///< per nonterminal: it gives its parent one value
  std::vector<int> bracket_delta;                ///< per terminal and end of input: +1 opens, -1 closes, 0
  std::vector<FinishFunction> finishes;          ///< the library's, run after the last sentence

  /// Whether `symbol` gives a value to the routine of the production it is
  /// in: data terminals do; a nonterminal does when one of its productions
  /// gives one (a routine with a result, or a lone symbol that gives one).
  bool gives(GrammarSymbol symbol) const;
};

/// Reads a grammar and builds its language.
/// @param[in]  source    the top grammar file
/// @param[in]  resolve   finds #Include files
/// @param[in]  routines  the routines productions may bind by name
/// @param[out] errors    what is wrong with the grammar, for its designer
/// @return the language, or nullopt with `errors` filled
std::optional<Language> load_language(const GrammarSource& source, const GrammarResolver& resolve,
                                      const RoutineLibrary& routines, std::vector<GrammarError>& errors);

}  // namespace fw::script
