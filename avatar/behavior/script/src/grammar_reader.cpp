#include "fw/script/grammar_reader.hpp"

#include <algorithm>
#include <map>
#include <string_view>

#include "fw/script/limits.hpp"
#include "word_chars.hpp"

namespace fw::script {
namespace {

bool is_word(std::string_view s) {
  return !s.empty() && is_word_start(s[0]) && std::all_of(s.begin(), s.end(), is_word_char);
}

bool is_nonterminal_name(std::string_view s) { return s.size() >= 3 && s.front() == '<' && s.back() == '>'; }

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > begin) words.push_back(line.substr(begin, i - begin));
  }
  return words;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Symbols and comment introducers must not start like a word, a number or a
// string, or the scanner could not tell where one token ends.
std::string symbol_spelling_problem(std::string_view spelling) {
  if (spelling.empty()) return "is empty";
  if (spelling.size() > kMaxSpellingBytes) return "is longer than " + std::to_string(kMaxSpellingBytes) + " characters";
  for (char c : spelling) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= 0x20 || byte >= 0x7f) return "may only hold printable ASCII characters without spaces";
  }
  if (is_word_char(spelling[0])) return "starts like a word or a number (declare words as keywords)";
  if (spelling[0] == '"') return "starts like a string";
  return {};
}

std::optional<TerminalKind> kind_from_word(std::string_view word) {
  for (TerminalKind kind : {TerminalKind::keyword, TerminalKind::symbol, TerminalKind::integer, TerminalKind::real,
                            TerminalKind::string, TerminalKind::identifier})
    if (word == terminal_kind_name(kind)) return kind;
  return std::nullopt;
}

// The paper's #Terminal list names its token classes IntLit, Reallit,
// StringLit and ID without saying how they are scanned; those names keep
// their obvious meaning so that the paper's grammar loads as printed.
TerminalKind default_kind(std::string_view name) {
  const std::string lower = lowercase(name);
  if (lower == "intlit") return TerminalKind::integer;
  if (lower == "reallit") return TerminalKind::real;
  if (lower == "stringlit") return TerminalKind::string;
  if (lower == "id") return TerminalKind::identifier;
  return is_word(name) ? TerminalKind::keyword : TerminalKind::symbol;
}

struct RawProduction {
  std::string lhs;
  std::vector<std::string> rhs;
  std::string routine;
  GrammarLocation where;
  bool in_top_file = false;
};

enum class Section { none, scanner, terminal, production };

class Reader {
 public:
  Reader(const GrammarResolver& resolve, std::vector<GrammarError>& errors) : resolve_(resolve), errors_(errors) {}

  void read_file(const GrammarSource& source, int depth) {
    if (++files_ > kMaxGrammarFiles) {
      error({source.name, 0}, "more than " + std::to_string(kMaxGrammarFiles) + " grammar files are included in all");
      return;
    }
    if (source.text.size() > kMaxGrammarBytes) {
      error({source.name, 0}, "the grammar is " + std::to_string(source.text.size()) + " bytes; at most " +
                                  std::to_string(kMaxGrammarBytes) + " are accepted");
      return;
    }
    const bool top = depth == 0;
    Section section = Section::none;
    bool ended = false;
    int line_number = 0;
    std::string_view text = source.text;
    while (!text.empty() && !ended && !too_many_errors()) {
      const std::size_t newline = text.find('\n');
      const std::string_view line = trim(text.substr(0, newline));
      text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
      ++line_number;
      const GrammarLocation where{source.name, line_number};
      if (line.empty()) continue;
      if (line[0] == '#') {
        if (line.size() == 1 || line[1] == ' ' || line[1] == '\t') continue;  // a comment
        const auto words = split_words(line);
        const std::string_view head = words[0];
        if (head == "#Scanner") section = Section::scanner;
        else if (head == "#Terminal") section = Section::terminal;
        else if (head == "#Production") section = Section::production;
        else if (head == "#End") ended = true;
        else if (head == "#Include") {
          include(where, trim(line.substr(head.size())), depth);
          section = Section::none;
          continue;
        } else {
          error(where, "unknown section " + std::string(head) +
                           "; a grammar has #Scanner, #Terminal, #Production, #Include and #End lines "
                           "(a comment line starts with '# ')");
          continue;
        }
        if (words.size() > 1 && !ended) error(where, std::string(head) + " stands alone on its line");
        continue;
      }
      switch (section) {
        case Section::none:
          error(where, "this line is outside any section; put it under #Terminal or #Production");
          break;
        case Section::scanner: scanner_line(where, split_words(line)); break;
        case Section::terminal: terminal_line(where, split_words(line)); break;
        case Section::production: production_line(where, split_words(line), top); break;
      }
    }
    if (!ended && !too_many_errors())
      error({source.name, line_number}, "the grammar has no #End line; it may be cut short (end it with #End)");
  }

  bool finish(Grammar& grammar, const std::string& name) {
    grammar = Grammar{};
    grammar.name = name;
    grammar.scanner = options_;
    grammar.terminals = terminals_;
    check_terminals(grammar);
    resolve_productions(grammar);
    return errors_.empty();
  }

 private:
  bool too_many_errors() const { return errors_.size() >= kMaxGrammarErrors; }

  void error(GrammarLocation where, std::string message) {
    if (too_many_errors()) return;
    errors_.push_back({std::move(where), std::move(message)});
  }

  void include(const GrammarLocation& where, std::string_view name, int depth) {
    if (name.empty()) {
      error(where, "#Include needs a file name, e.g. #Include expression.grammar");
      return;
    }
    if (depth + 1 > kMaxIncludeDepth) {
      error(where, "includes nest deeper than " + std::to_string(kMaxIncludeDepth) + " files (does a file include itself?)");
      return;
    }
    std::optional<GrammarSource> included;
    if (resolve_) included = resolve_(where.file, std::string(name));
    if (!included) {
      error(where, "cannot find the included grammar '" + std::string(name) + "'");
      return;
    }
    read_file(*included, depth + 1);
  }

  void scanner_line(const GrammarLocation& where, const std::vector<std::string_view>& words) {
    if (words.size() == 2 && words[0] == "comment") {
      const std::string introducer(words[1]);
      if (const std::string problem = symbol_spelling_problem(introducer); !problem.empty()) {
        error(where, "the comment introducer '" + introducer + "' " + problem);
        return;
      }
      if (std::find(options_.comment_introducers.begin(), options_.comment_introducers.end(), introducer) !=
          options_.comment_introducers.end())
        return;
      if (options_.comment_introducers.size() >= kMaxCommentIntroducers) {
        error(where, "at most " + std::to_string(kMaxCommentIntroducers) + " comment introducers");
        return;
      }
      options_.comment_introducers.push_back(introducer);
      return;
    }
    if (words.size() == 2 && words[0] == "keywords" && (words[1] == "case-sensitive" || words[1] == "case-insensitive")) {
      const bool ignore_case = words[1] == "case-insensitive";
      if (case_where_ && options_.keywords_ignore_case != ignore_case) {
        error(where, "keyword case is set both ways (also at " + location_text(*case_where_) + ")");
        return;
      }
      options_.keywords_ignore_case = ignore_case;
      case_where_ = where;
      return;
    }
    error(where, "a #Scanner line is 'comment INTRODUCER' or 'keywords case-sensitive' or 'keywords case-insensitive'");
  }

  void terminal_line(const GrammarLocation& where, const std::vector<std::string_view>& words) {
    Terminal terminal;
    terminal.name = std::string(words[0]);
    terminal.where = where;
    if (is_nonterminal_name(terminal.name) || terminal.name == "::=" || terminal.name == "=>") {
      error(where, "'" + terminal.name +
                       "' cannot name a terminal (it reads as a nonterminal or as production syntax); give the "
                       "terminal another name and its spelling after the kind, e.g. 'Arrow symbol =>'");
      return;
    }
    if (words.size() > 3) {
      error(where, "a terminal line is NAME [KIND [SPELLING]]");
      return;
    }
    if (words.size() >= 2) {
      const auto kind = kind_from_word(words[1]);
      if (!kind) {
        error(where, "unknown terminal kind '" + std::string(words[1]) +
                         "'; use keyword, symbol, integer, real, string or identifier");
        return;
      }
      terminal.kind = *kind;
    } else {
      terminal.kind = default_kind(terminal.name);
    }
    const bool spelled = terminal.kind == TerminalKind::keyword || terminal.kind == TerminalKind::symbol;
    if (words.size() == 3 && !spelled) {
      error(where, "only keywords and symbols have a spelling; a " + std::string(terminal_kind_name(terminal.kind)) +
                       " terminal is scanned by its kind");
      return;
    }
    if (spelled) terminal.spelling = std::string(words.size() == 3 ? words[2] : words[0]);
    if (terminal.kind == TerminalKind::keyword &&
        (!is_word(terminal.spelling) || terminal.spelling.size() > kMaxSpellingBytes)) {
      error(where, "the keyword '" + terminal.spelling + "' must be a word of at most " +
                       std::to_string(kMaxSpellingBytes) +
                       " letters, digits and '_' that does not start with a digit (declare punctuation as a symbol)");
      return;
    }
    if (terminal.kind == TerminalKind::symbol) {
      if (const std::string problem = symbol_spelling_problem(terminal.spelling); !problem.empty()) {
        error(where, "the symbol '" + terminal.spelling + "' " + problem);
        return;
      }
    }
    for (const Terminal& existing : terminals_) {
      if (existing.name != terminal.name) continue;
      // The same declaration twice is harmless (the paper's own list repeats
      // ')'), and included grammars share terminals such as `end`.
      if (existing.kind != terminal.kind || existing.spelling != terminal.spelling)
        error(where, "terminal " + terminal.name + " is declared differently at " + location_text(existing.where));
      return;
    }
    if (terminals_.size() >= kMaxTerminals) {
      error(where, "more than " + std::to_string(kMaxTerminals) + " terminals");
      return;
    }
    terminals_.push_back(std::move(terminal));
  }

  void production_line(const GrammarLocation& where, const std::vector<std::string_view>& words, bool top) {
    if (words.size() < 2 || !is_nonterminal_name(words[0]) || words[1] != "::=") {
      error(where, "a production reads <NAME> ::= SYMBOLS... [=> routine]");
      return;
    }
    RawProduction production;
    production.lhs = std::string(words[0].substr(1, words[0].size() - 2));
    production.where = where;
    production.in_top_file = top;
    std::size_t i = 2;
    for (; i < words.size() && words[i] != "=>"; ++i) production.rhs.emplace_back(words[i]);
    if (i < words.size()) {
      if (i + 2 != words.size() || !is_word(words[i + 1])) {
        error(where, "'=>' is followed by one routine name (letters, digits and '_') at the end of the line");
        return;
      }
      production.routine = std::string(words[i + 1]);
    }
    if (production.rhs.size() > kMaxRhsSymbols) {
      error(where, "more than " + std::to_string(kMaxRhsSymbols) + " symbols on the right of one production");
      return;
    }
    if (productions_.size() >= kMaxProductions) {
      error(where, "more than " + std::to_string(kMaxProductions) + " productions");
      return;
    }
    productions_.push_back(std::move(production));
  }

  void check_terminals(const Grammar& grammar) {
    std::map<TerminalKind, const Terminal*> by_class;
    std::map<std::string, const Terminal*> by_spelling;
    for (const Terminal& t : grammar.terminals) {
      if (!carries_data(t.kind)) {
        const std::string key = (t.kind == TerminalKind::keyword && grammar.scanner.keywords_ignore_case)
                                    ? lowercase(t.spelling)
                                    : t.spelling;
        const auto [at, fresh] = by_spelling.emplace(key, &t);
        if (!fresh)
          error(t.where, "terminals " + at->second->name + " and " + t.name + " are both spelled '" + t.spelling +
                             "'; the scanner could not tell them apart");
        continue;
      }
      const auto [at, fresh] = by_class.emplace(t.kind, &t);
      if (!fresh)
        error(t.where, "terminals " + at->second->name + " and " + t.name + " are both of kind " +
                           std::string(terminal_kind_name(t.kind)) + "; the scanner could not tell them apart");
    }
    for (const std::string& introducer : grammar.scanner.comment_introducers)
      if (const auto at = by_spelling.find(introducer); at != by_spelling.end())
        error(at->second->where, "the symbol '" + introducer + "' is also the comment introducer");
  }

  int nonterminal(Grammar& grammar, const std::string& name) {
    const int index = grammar.nonterminal_index(name);
    if (index >= 0) return index;
    grammar.nonterminals.push_back(name);
    return static_cast<int>(grammar.nonterminals.size()) - 1;
  }

  void resolve_productions(Grammar& grammar) {
    // Left-hand sides first, so that nonterminal numbers follow the order in
    // which they are defined.
    for (const RawProduction& raw : productions_) nonterminal(grammar, raw.lhs);
    const std::size_t defined = grammar.nonterminals.size();
    std::vector<GrammarLocation> first_use;
    int start = -1;
    for (const RawProduction& raw : productions_) {
      Production production;
      production.lhs = grammar.nonterminal_index(raw.lhs);
      production.routine = raw.routine;
      production.where = raw.where;
      bool ok = true;
      for (const std::string& word : raw.rhs) {
        if (is_nonterminal_name(word)) {
          const int index = nonterminal(grammar, word.substr(1, word.size() - 2));
          if (static_cast<std::size_t>(index) >= defined + first_use.size()) first_use.push_back(raw.where);
          production.rhs.push_back({false, index});
          continue;
        }
        const int index = grammar.terminal_index(word);
        if (index < 0) {
          error(raw.where, "'" + word + "' is not declared under #Terminal; declare it there, or write <" + word +
                               "> if it is a nonterminal");
          ok = false;
          continue;
        }
        production.rhs.push_back({true, index});
      }
      if (!ok) continue;
      if (!same_as_earlier(grammar, production)) {
        if (raw.in_top_file && start < 0) start = production.lhs;
        grammar.productions.push_back(std::move(production));
      }
    }
    for (std::size_t i = defined; i < grammar.nonterminals.size(); ++i)
      error(first_use[i - defined], "<" + grammar.nonterminals[i] + "> is used here but no production defines it");
    if (grammar.nonterminals.size() > kMaxNonterminals)
      error({grammar.name, 0}, "more than " + std::to_string(kMaxNonterminals) + " nonterminals");
    if (grammar.productions.empty()) {
      error({grammar.name, 0}, "the grammar has no productions; list them under #Production");
      return;
    }
    grammar.start = start >= 0 ? start : grammar.productions.front().lhs;
  }

  // Included grammars may share productions (both default languages define
  // <STEPS> ::= IntLit); a repeat is dropped, a repeat bound to another
  // routine is a contradiction.
  bool same_as_earlier(const Grammar& grammar, const Production& production) {
    for (const Production& earlier : grammar.productions) {
      if (earlier.lhs != production.lhs || earlier.rhs != production.rhs) continue;
      if (earlier.routine != production.routine)
        error(production.where, "this production is also written at " + location_text(earlier.where) +
                                    " with another routine ('" + earlier.routine + "' there, '" + production.routine +
                                    "' here)");
      return true;
    }
    return false;
  }

  const GrammarResolver& resolve_;
  std::vector<GrammarError>& errors_;
  ScannerOptions options_;
  std::optional<GrammarLocation> case_where_;
  std::vector<Terminal> terminals_;
  std::vector<RawProduction> productions_;
  std::size_t files_ = 0;
};

}  // namespace

bool read_grammar(const GrammarSource& source, const GrammarResolver& resolve, Grammar& grammar,
                  std::vector<GrammarError>& errors) {
  errors.clear();
  Reader reader(resolve, errors);
  reader.read_file(source, 0);
  return reader.finish(grammar, source.name);
}

}  // namespace fw::script
