#include "fw/script/language.hpp"

namespace fw::script {
namespace {

ValueKinds terminal_kinds(TerminalKind kind) {
  switch (kind) {
    case TerminalKind::integer: return kinds_of(ValueKind::integer);
    case TerminalKind::real: return kinds_of(ValueKind::real);
    case TerminalKind::string:
    case TerminalKind::identifier: return kinds_of(ValueKind::text);
    case TerminalKind::keyword:
    case TerminalKind::symbol: break;
  }
  return kinds_of(ValueKind::none);
}

std::string symbol_name(const Grammar& grammar, GrammarSymbol s) {
  return s.terminal ? grammar.terminals[static_cast<std::size_t>(s.index)].name
                    : "<" + grammar.nonterminals[static_cast<std::size_t>(s.index)] + ">";
}

int bracket_of(const Terminal& t) {
  if (t.kind != TerminalKind::symbol) return 0;
  if (t.spelling == "[" || t.spelling == "(" || t.spelling == "{") return 1;
  if (t.spelling == "]" || t.spelling == ")" || t.spelling == "}") return -1;
  return 0;
}

// Binds routines by name and works out which symbols give values, then
// checks that each routine gets the values it takes. Mistakes here are the
// designer's, so they are found when the grammar loads, not when a user's
// sentence happens to use the production.
void bind(Language& language, const RoutineLibrary& library, std::vector<GrammarError>& errors) {
  const Grammar& g = language.grammar;
  const auto error = [&](GrammarLocation where, std::string message) {
    if (errors.size() < kMaxGrammarErrors) errors.push_back({std::move(where), std::move(message)});
  };
  language.routines.assign(g.productions.size(), std::nullopt);
  for (std::size_t p = 0; p < g.productions.size(); ++p) {
    const Production& production = g.productions[p];
    if (production.routine.empty()) continue;
    if (const Routine* routine = library.find(production.routine)) {
      language.routines[p] = *routine;
      continue;
    }
    std::string known;
    for (const Routine& r : library.routines()) known += (known.empty() ? "" : ", ") + r.name;
    error(production.where, "the routine '" + production.routine + "' is not in the routine library; it has: " +
                                (known.empty() ? std::string("none") : known));
  }
  if (!errors.empty()) return;

  // Which nonterminals give a value: a fixed point that only grows.
  language.nonterminal_gives.assign(g.nonterminals.size(), false);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t p = 0; p < g.productions.size(); ++p) {
      const Production& production = g.productions[p];
      const auto& routine = language.routines[p];
      const bool gives = routine ? routine->result != ValueKind::none
                                 : production.rhs.size() == 1 && language.gives(production.rhs[0]);
      if (gives && !language.nonterminal_gives[static_cast<std::size_t>(production.lhs)])
        language.nonterminal_gives[static_cast<std::size_t>(production.lhs)] = changed = true;
    }
  }
  // And of which kinds, now that `gives` is final.
  std::vector<ValueKinds> kinds(g.nonterminals.size(), 0);
  const auto kinds_of_symbol = [&](GrammarSymbol s) {
    return s.terminal ? terminal_kinds(g.terminals[static_cast<std::size_t>(s.index)].kind)
                      : kinds[static_cast<std::size_t>(s.index)];
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t p = 0; p < g.productions.size(); ++p) {
      const Production& production = g.productions[p];
      const auto& routine = language.routines[p];
      ValueKinds k = kinds_of(ValueKind::none);
      if (routine) k = kinds_of(routine->result);
      else if (production.rhs.size() == 1 && language.gives(production.rhs[0])) k = kinds_of_symbol(production.rhs[0]);
      ValueKinds& target = kinds[static_cast<std::size_t>(production.lhs)];
      if ((target | k) != target) {
        target |= k;
        changed = true;
      }
    }
  }

  language.value_slots.assign(g.productions.size(), 0);
  for (std::size_t p = 0; p < g.productions.size(); ++p) {
    const Production& production = g.productions[p];
    std::vector<GrammarSymbol> giving;
    for (const GrammarSymbol& s : production.rhs)
      if (language.gives(s)) giving.push_back(s);
    language.value_slots[p] = static_cast<int>(giving.size());
    const auto& routine = language.routines[p];
    if (!routine) continue;
    if (giving.size() != routine->parameters.size()) {
      std::string given, taken;
      for (const GrammarSymbol& s : giving)
        given += (given.empty() ? "" : ", ") + symbol_name(g, s) + " (" + describe_kinds(kinds_of_symbol(s)) + ")";
      for (const RoutineParameter& parameter : routine->parameters)
        taken += (taken.empty() ? "" : ", ") + parameter.meaning + " (" + describe_kinds(parameter.accepts) + ")";
      error(production.where, production_text(g, production) + " gives " + std::to_string(giving.size()) +
                                  " value(s)" + (given.empty() ? "" : ": " + given) + "; but " + routine->name +
                                  " takes " + std::to_string(routine->parameters.size()) +
                                  (taken.empty() ? "" : ": " + taken));
      continue;
    }
    for (std::size_t i = 0; i < giving.size(); ++i) {
      const ValueKinds k = kinds_of_symbol(giving[i]);
      const RoutineParameter& parameter = routine->parameters[i];
      if ((k & ~parameter.accepts) == 0) continue;
      error(production.where, production_text(g, production) + ": " + routine->name + " takes " + parameter.meaning +
                                  " as value " + std::to_string(i + 1) + ", which must be " +
                                  describe_kinds(parameter.accepts) + ", but " + symbol_name(g, giving[i]) +
                                  " can give " + describe_kinds(k));
    }
  }
}

}  // namespace

bool Language::gives(GrammarSymbol symbol) const {
  if (symbol.terminal) return carries_data(grammar.terminals[static_cast<std::size_t>(symbol.index)].kind);
  return nonterminal_gives[static_cast<std::size_t>(symbol.index)];
}

std::optional<Language> load_language(const GrammarSource& source, const GrammarResolver& resolve,
                                      const RoutineLibrary& routines, std::vector<GrammarError>& errors) {
  Language language;
  if (!read_grammar(source, resolve, language.grammar, errors)) return std::nullopt;
  std::string scan_error;
  if (!build_scan_table(language.grammar, language.scan, scan_error)) {
    GrammarError error;
    error.where.file = source.name;
    error.message = std::move(scan_error);
    errors.push_back(std::move(error));
    return std::nullopt;
  }
  if (!build_parse_table(language.grammar, language.parse, errors)) return std::nullopt;
  bind(language, routines, errors);
  if (!errors.empty()) return std::nullopt;
  for (const Terminal& t : language.grammar.terminals) language.bracket_delta.push_back(bracket_of(t));
  language.bracket_delta.push_back(0);  // end of input
  language.finishes = routines.finishes();
  return language;
}

}  // namespace fw::script
