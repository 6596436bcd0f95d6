#pragma once
// A language definition as read from grammar files: how each terminal is
// scanned, the productions, and the semantic routine bound to each
// production by name. Plain data; grammar_reader.hpp fills it, scan_table.hpp
// and parse_table.hpp turn it into the tables the fixed drivers run on.
#include <string>
#include <string_view>
#include <vector>

namespace fw::script {

/// How the scanner recognises a terminal.
enum class TerminalKind : unsigned char {
  keyword,     ///< a word spelled exactly as `spelling` (letters, digits, '_'; not starting with a digit)
  symbol,      ///< punctuation spelled as `spelling`, e.g. "[" or ":"
  integer,     ///< [+-]?digits
  real,        ///< [+-]?digits.digits, exponent allowed; also plain digits if no integer terminal exists
  string,      ///< "..." on one line; \" and \\ are the only escapes
  identifier,  ///< [A-Za-z_][A-Za-z0-9_]* that is not a keyword
};
std::string_view terminal_kind_name(TerminalKind kind);
/// Whether tokens of this kind carry data (a number or text) to the routines.
constexpr bool carries_data(TerminalKind kind) { return kind != TerminalKind::keyword && kind != TerminalKind::symbol; }

/// Where a line of a grammar came from, for messages.
struct GrammarLocation {
  std::string file;
  int line = 0;
};

struct Terminal {
  std::string name;      ///< as used in productions
  TerminalKind kind = TerminalKind::keyword;
  std::string spelling;  ///< keywords and symbols only
  GrammarLocation where;
};

/// A symbol on the right of a production: a terminal or a nonterminal index.
struct GrammarSymbol {
  bool terminal = true;
  int index = 0;
  friend bool operator==(const GrammarSymbol&, const GrammarSymbol&) = default;
};

struct Production {
  int lhs = 0;                     ///< nonterminal index
  std::vector<GrammarSymbol> rhs;  ///< empty: the production derives nothing
  std::string routine;             ///< the semantic routine run when it is recognised; empty for none
  GrammarLocation where;
};

/// Scanner settings that are not terminals.
struct ScannerOptions {
  std::vector<std::string> comment_introducers;  ///< each starts a comment that runs to the end of the line
  bool keywords_ignore_case = false;
};

struct Grammar {
  std::string name;  ///< the top grammar file, for messages
  ScannerOptions scanner;
  std::vector<Terminal> terminals;
  std::vector<std::string> nonterminals;  ///< names without the angle brackets
  std::vector<Production> productions;
  int start = 0;  ///< nonterminal every sentence derives from

  /// Index of the terminal or nonterminal called `name`, or -1.
  int terminal_index(std::string_view name) const;
  int nonterminal_index(std::string_view name) const;
  /// The pseudo-terminal that marks the end of the input: terminals.size().
  int end_of_input() const { return static_cast<int>(terminals.size()); }
};

/// A problem with a grammar, for the designer who wrote it.
struct GrammarError {
  GrammarLocation where;  ///< line 0: the file as a whole
  std::string message;
};
/// `file:line: message` (or `file: message` for line 0).
std::string format_grammar_error(const GrammarError& error);

/// `<AUHEAD> ::= <AUID> <STRENGTH>` (with ` => routine` if bound), for messages.
std::string production_text(const Grammar& grammar, const Production& production);
/// `file:line`
std::string location_text(const GrammarLocation& where);
/// What a person should type for `terminal`: 'Animate', '[', an integer,
/// a name...; end_of_input() is "end of file".
std::string describe_terminal(const Grammar& grammar, int terminal);

}  // namespace fw::script
