#include "fw/script/grammar.hpp"

namespace fw::script {

std::string_view terminal_kind_name(TerminalKind kind) {
  switch (kind) {
    case TerminalKind::keyword: return "keyword";
    case TerminalKind::symbol: return "symbol";
    case TerminalKind::integer: return "integer";
    case TerminalKind::real: return "real";
    case TerminalKind::string: return "string";
    case TerminalKind::identifier: return "identifier";
  }
  return "?";
}

int Grammar::terminal_index(std::string_view wanted) const {
  for (std::size_t i = 0; i < terminals.size(); ++i)
    if (terminals[i].name == wanted) return static_cast<int>(i);
  return -1;
}

int Grammar::nonterminal_index(std::string_view wanted) const {
  for (std::size_t i = 0; i < nonterminals.size(); ++i)
    if (nonterminals[i] == wanted) return static_cast<int>(i);
  return -1;
}

std::string production_text(const Grammar& grammar, const Production& production) {
  std::string out = "<" + grammar.nonterminals[static_cast<std::size_t>(production.lhs)] + "> ::=";
  for (const GrammarSymbol& symbol : production.rhs) {
    out += ' ';
    if (symbol.terminal) out += grammar.terminals[static_cast<std::size_t>(symbol.index)].name;
    else out += "<" + grammar.nonterminals[static_cast<std::size_t>(symbol.index)] + ">";
  }
  if (production.rhs.empty()) out += " (nothing)";
  if (!production.routine.empty()) out += " => " + production.routine;
  return out;
}

std::string location_text(const GrammarLocation& where) { return where.file + ":" + std::to_string(where.line); }

std::string format_grammar_error(const GrammarError& error) {
  return (error.where.line > 0 ? location_text(error.where) : error.where.file) + ": " + error.message;
}

std::string describe_terminal(const Grammar& grammar, int terminal) {
  if (terminal == grammar.end_of_input()) return "end of file";
  const Terminal& t = grammar.terminals[static_cast<std::size_t>(terminal)];
  switch (t.kind) {
    case TerminalKind::keyword:
    case TerminalKind::symbol: return "'" + t.spelling + "'";
    case TerminalKind::integer: return "an integer";
    case TerminalKind::real: return "a decimal number";
    case TerminalKind::string: return "a \"string\"";
    case TerminalKind::identifier: return "a name";
  }
  return t.name;
}

}  // namespace fw::script
