#include "fw/script/parse_table.hpp"

#include <map>

namespace fw::script {
namespace {

// FIRST of the symbols rhs[from..], and whether they can all derive nothing.
TerminalSet first_of(const std::vector<GrammarSymbol>& rhs, std::size_t from, const ParseTable& t, bool& nullable) {
  TerminalSet set;
  nullable = true;
  for (std::size_t i = from; i < rhs.size() && nullable; ++i) {
    const GrammarSymbol s = rhs[i];
    if (s.terminal) {
      set.set(static_cast<std::size_t>(s.index));
      nullable = false;
    } else {
      set |= t.first[static_cast<std::size_t>(s.index)];
      nullable = t.nullable[static_cast<std::size_t>(s.index)];
    }
  }
  return set;
}

std::string terminal_list(const Grammar& grammar, const TerminalSet& set) {
  std::string out;
  int shown = 0;
  for (int t = 0; t <= grammar.end_of_input(); ++t) {
    if (!set.test(static_cast<std::size_t>(t))) continue;
    if (shown++) out += ", ";
    out += t == grammar.end_of_input() ? std::string("end of file") : "'" + grammar.terminals[static_cast<std::size_t>(t)].name + "'";
  }
  return out;
}

}  // namespace

TerminalSet ParseTable::expected(int nonterminal) const {
  TerminalSet set;
  for (int t = 0; t < columns; ++t)
    if (production_for(nonterminal, t) != kNoProduction) set.set(static_cast<std::size_t>(t));
  return set;
}

bool build_parse_table(const Grammar& grammar, ParseTable& table, std::vector<GrammarError>& errors) {
  errors.clear();
  const auto error = [&](GrammarLocation where, std::string message) {
    if (errors.size() < kMaxGrammarErrors) errors.push_back({std::move(where), std::move(message)});
  };
  const std::size_t n = grammar.nonterminals.size();
  ParseTable t;
  t.columns = grammar.end_of_input() + 1;
  t.nullable.assign(n, false);
  t.first.assign(n, {});
  t.follow.assign(n, {});

  // Every nonterminal must derive some string of terminals, or sentences
  // through it could never be finished.
  std::vector<bool> productive(n, false);
  for (bool changed = true; changed;) {
    changed = false;
    for (const Production& p : grammar.productions) {
      if (productive[static_cast<std::size_t>(p.lhs)]) continue;
      bool all = true;
      for (const GrammarSymbol& s : p.rhs) all = all && (s.terminal || productive[static_cast<std::size_t>(s.index)]);
      if (all) productive[static_cast<std::size_t>(p.lhs)] = changed = true;
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    if (productive[a]) continue;
    GrammarLocation where{grammar.name, 0};
    for (const Production& p : grammar.productions)
      if (static_cast<std::size_t>(p.lhs) == a) {
        where = p.where;
        break;
      }
    error(where, "<" + grammar.nonterminals[a] +
                     "> never derives a finished sentence: each of its productions needs itself, or another "
                     "nonterminal that cannot finish; give it a production that ends");
  }
  if (!errors.empty()) return false;

  // FIRST and nullable, to a fixed point.
  for (bool changed = true; changed;) {
    changed = false;
    for (const Production& p : grammar.productions) {
      const auto a = static_cast<std::size_t>(p.lhs);
      bool nullable = false;
      const TerminalSet first = first_of(p.rhs, 0, t, nullable);
      if ((t.first[a] | first) != t.first[a]) {
        t.first[a] |= first;
        changed = true;
      }
      if (nullable && !t.nullable[a]) t.nullable[a] = changed = true;
    }
  }
  const auto start = static_cast<std::size_t>(grammar.start);
  if (t.nullable[start]) {
    error({grammar.name, 0}, "the start symbol <" + grammar.nonterminals[start] +
                                 "> can derive an empty sentence; every sentence must hold at least one token");
    return false;
  }

  // FOLLOW. A script is a sequence of sentences, so a sentence may be
  // followed by the end of the input or by the start of the next sentence.
  t.follow[start].set(static_cast<std::size_t>(grammar.end_of_input()));
  t.follow[start] |= t.first[start];
  for (bool changed = true; changed;) {
    changed = false;
    for (const Production& p : grammar.productions) {
      for (std::size_t i = 0; i < p.rhs.size(); ++i) {
        if (p.rhs[i].terminal) continue;
        const auto b = static_cast<std::size_t>(p.rhs[i].index);
        bool rest_nullable = false;
        TerminalSet add = first_of(p.rhs, i + 1, t, rest_nullable);
        if (rest_nullable) add |= t.follow[static_cast<std::size_t>(p.lhs)];
        if ((t.follow[b] | add) != t.follow[b]) {
          t.follow[b] |= add;
          changed = true;
        }
      }
    }
  }

  // The table, and every pair of productions that compete for a lookahead.
  t.entries.assign(n * static_cast<std::size_t>(t.columns), ParseTable::kNoProduction);
  std::map<std::pair<int, int>, TerminalSet> conflicts;
  for (std::size_t pi = 0; pi < grammar.productions.size(); ++pi) {
    const Production& p = grammar.productions[pi];
    bool nullable = false;
    TerminalSet predict = first_of(p.rhs, 0, t, nullable);
    if (nullable) predict |= t.follow[static_cast<std::size_t>(p.lhs)];
    for (int terminal = 0; terminal < t.columns; ++terminal) {
      if (!predict.test(static_cast<std::size_t>(terminal))) continue;
      std::int16_t& entry =
          t.entries[static_cast<std::size_t>(p.lhs) * static_cast<std::size_t>(t.columns) + static_cast<std::size_t>(terminal)];
      if (entry == ParseTable::kNoProduction) entry = static_cast<std::int16_t>(pi);
      else conflicts[{entry, static_cast<int>(pi)}].set(static_cast<std::size_t>(terminal));
    }
  }
  for (const auto& [pair, lookahead] : conflicts) {
    const Production& p1 = grammar.productions[static_cast<std::size_t>(pair.first)];
    const Production& p2 = grammar.productions[static_cast<std::size_t>(pair.second)];
    bool n1 = false, n2 = false;
    first_of(p1.rhs, 0, t, n1);
    first_of(p2.rhs, 0, t, n2);
    std::string why = "both start with it";
    if (n1 || n2) why = "one of them can derive nothing and it can follow <" + grammar.nonterminals[static_cast<std::size_t>(p1.lhs)] + ">";
    error(p2.where, "the grammar is not LL(1): <" + grammar.nonterminals[static_cast<std::size_t>(p1.lhs)] +
                        "> has two productions for the lookahead " + terminal_list(grammar, lookahead) + ": " +
                        production_text(grammar, p1) + " (" + location_text(p1.where) + ") and " +
                        production_text(grammar, p2) + " (" + location_text(p2.where) + "); " + why +
                        ". Rewrite them so that one terminal of lookahead decides (factor out the common start, "
                        "or remove left recursion)");
  }
  if (!errors.empty()) return false;
  table = std::move(t);
  return true;
}

}  // namespace fw::script
