#pragma once
// The LL(1) parser generator: FIRST and FOLLOW sets and the parse table that
// the one fixed parser driver (parser.hpp) runs. A grammar that is not
// LL(1) is rejected with every conflict named: the nonterminal, the
// productions that compete and the lookahead terminals they compete for.
#include <bitset>
#include <cstdint>
#include <vector>

#include "fw/script/grammar.hpp"
#include "fw/script/limits.hpp"

namespace fw::script {

/// A set of terminals, end of input included (index Grammar::end_of_input()).
using TerminalSet = std::bitset<kMaxTerminals + 1>;

struct ParseTable {
  static constexpr std::int16_t kNoProduction = -1;

  int columns = 0;                    ///< terminals + 1 (end of input)
  std::vector<std::int16_t> entries;  ///< [nonterminal * columns + terminal] -> production or kNoProduction
  std::vector<bool> nullable;         ///< per nonterminal: can derive nothing
  std::vector<TerminalSet> first;     ///< per nonterminal
  std::vector<TerminalSet> follow;    ///< per nonterminal; a sentence may be followed by another sentence

  std::int16_t production_for(int nonterminal, int terminal) const {
    return entries[static_cast<std::size_t>(nonterminal) * static_cast<std::size_t>(columns) +
                   static_cast<std::size_t>(terminal)];
  }
  /// The terminals for which `nonterminal` has a production.
  TerminalSet expected(int nonterminal) const;
};

/// Builds the LL(1) table of `grammar`. Fails when a nonterminal cannot
/// derive any sentence, when the start symbol can derive an empty sentence
/// (a script is a sequence of sentences, each at least one token long), or
/// on LL(1) conflicts.
/// @param[out] table   the table, complete only on success
/// @param[out] errors  one entry per problem, at most kMaxGrammarErrors
/// @return true on success
bool build_parse_table(const Grammar& grammar, ParseTable& table, std::vector<GrammarError>& errors);

}  // namespace fw::script
