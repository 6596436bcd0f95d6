#pragma once
// The scanner generator: turns the terminals of a grammar into the tables of
// a deterministic automaton (byte classes, transitions, accepting states)
// that the one fixed scanner driver (scanner.hpp) runs. Built by subset
// construction from a small NFA per terminal, so any set of keywords,
// symbols and comment introducers works without code changes.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fw/script/grammar.hpp"

namespace fw::script {

struct ScanTable {
  static constexpr std::int16_t kNoState = -1;
  /// accept[] values below 0; values >= 0 are terminal indices.
  static constexpr std::int16_t kAcceptNothing = -1;
  static constexpr std::int16_t kAcceptSkip = -2;         ///< white space and comments
  static constexpr std::int16_t kAcceptUnknownWord = -3;  ///< a word that is no keyword, when there is no identifier

  std::array<std::uint8_t, 256> byte_class{};  ///< bytes the automaton never tells apart share a class
  int class_count = 0;
  std::vector<std::int16_t> next;    ///< [state * class_count + class] -> state or kNoState; state 0 starts
  std::vector<std::int16_t> accept;  ///< per state: terminal, or one of the kAccept values
  std::vector<TerminalKind> terminal_kinds;  ///< per terminal, to convert lexemes into values
  int end_of_input = 0;                      ///< the terminal index of the end of input

  int state_count() const { return static_cast<int>(accept.size()); }
  std::int16_t step(int state, unsigned char byte) const {
    return next[static_cast<std::size_t>(state) * static_cast<std::size_t>(class_count) + byte_class[byte]];
  }
};

/// Builds the scan table for `grammar`'s terminals and scanner options.
/// Longest match wins; at equal length keywords and symbols beat comments,
/// which beat integers, reals, strings and identifiers, in that order.
/// @param[out] table  the tables, complete only on success
/// @param[out] error  why not, on failure (too many states)
/// @return true on success
bool build_scan_table(const Grammar& grammar, ScanTable& table, std::string& error);

}  // namespace fw::script
