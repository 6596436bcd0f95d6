#include "fw/script/parser.hpp"

#include <algorithm>

#include "fw/script/limits.hpp"
#include "fw/script/scanner.hpp"
#include "fw/script/semantic_handler.hpp"

namespace fw::script {
namespace {

// An LL(1) grammar without left recursion (load_language guarantees both)
// reads a token within a bounded number of expansions; this only guards the
// drivers against a bug turning into a hang.
constexpr std::size_t kMaxExpansionsWithoutInput = kMaxParseStackDepth * kMaxNonterminals;

struct StackEntry {
  bool completion = false;  ///< a marker: call the routine of `production`
  GrammarSymbol symbol;
  int production = 0;
  bool wanted = false;
  SourcePosition at;
};

class Driver {
 public:
  Driver(const Language& language, std::string_view text, ScriptBuilder& script, DiagnosticList& diagnostics)
      : language_(language),
        grammar_(language.grammar),
        scanner_(language.scan, text),
        handler_(language, script, diagnostics),
        diagnostics_(diagnostics) {}

  std::size_t run() {
    std::size_t sentences = 0;
    look_ = scanner_.next();
    while (look_.terminal != grammar_.end_of_input() && !diagnostics_.full()) {
      if (sentences >= kMaxSentences) {
        diagnostics_.error(look_.position, "more than " + std::to_string(kMaxSentences) +
                                               " sentences in one script; split it into several");
        break;
      }
      const SourcePosition start = look_.position;
      handler_.begin_sentence();
      depth_ = 0;
      consumed_ = false;
      const bool parsed = parse_sentence(start);
      handler_.end_sentence(parsed, start);
      ++sentences;
      if (!parsed) recover();
    }
    if (sentences == 0 && diagnostics_.error_count() == 0)
      diagnostics_.warning(look_.position, "the script holds no sentences");
    handler_.finish();
    return sentences;
  }

 private:
  void advance() {
    depth_ += language_.bracket_delta[static_cast<std::size_t>(look_.terminal < 0 ? grammar_.end_of_input() : look_.terminal)];
    consumed_ = true;
    look_ = scanner_.next();
  }

  bool parse_sentence(SourcePosition start) {
    stack_.clear();
    stack_.push_back({false, {false, grammar_.start}, 0, false, look_.position});
    TerminalSet also_expected;  // what productions expanded at this lookahead could also have read
    std::size_t expansions = 0;
    while (!stack_.empty()) {
      const StackEntry entry = stack_.back();
      stack_.pop_back();
      if (entry.completion) {
        handler_.complete(entry.production, entry.wanted, entry.at);
        continue;
      }
      if (entry.symbol.terminal) {
        if (look_.terminal == entry.symbol.index) {
          handler_.shift(look_, entry.wanted);
          advance();
          also_expected.reset();
          expansions = 0;
          continue;
        }
        also_expected.set(static_cast<std::size_t>(entry.symbol.index));
        syntax_error(also_expected, start);
        return false;
      }
      const int production =
          look_.terminal < 0 ? ParseTable::kNoProduction : language_.parse.production_for(entry.symbol.index, look_.terminal);
      also_expected |= language_.parse.expected(entry.symbol.index);
      if (production == ParseTable::kNoProduction) {
        syntax_error(also_expected, start);
        return false;
      }
      const Production& p = grammar_.productions[static_cast<std::size_t>(production)];
      if (stack_.size() + p.rhs.size() + 1 > kMaxParseStackDepth) {
        diagnostics_.error(look_.position, "this sentence nests too deeply (more than " +
                                               std::to_string(kMaxParseStackDepth) +
                                               " open symbols); split it or nest less");
        return false;
      }
      if (++expansions > kMaxExpansionsWithoutInput) {
        diagnostics_.error(look_.position, "internal error: the parser made no progress; the grammar may loop");
        return false;
      }
      const auto plan = handler_.expand(production, entry.wanted, look_.position);
      if (plan.complete_later) stack_.push_back({true, {}, production, entry.wanted, look_.position});
      for (auto s = p.rhs.rbegin(); s != p.rhs.rend(); ++s)
        stack_.push_back({false, *s, 0, plan.children_wanted && language_.gives(*s), {}});
    }
    return true;
  }

  std::string found_text() const {
    if (look_.terminal == grammar_.end_of_input()) return "end of file";
    const std::string lexeme = printable(look_.lexeme);
    switch (grammar_.terminals[static_cast<std::size_t>(look_.terminal)].kind) {
      case TerminalKind::keyword:
      case TerminalKind::symbol: return "'" + lexeme + "'";
      case TerminalKind::integer: return "the integer " + lexeme;
      case TerminalKind::real: return "the decimal number " + lexeme;
      case TerminalKind::string: return "the string " + lexeme;
      case TerminalKind::identifier: return "the name '" + lexeme + "'";
    }
    return lexeme;
  }

  std::string expected_text(const TerminalSet& expected) const {
    std::vector<std::string> items;
    for (int t = 0; t <= grammar_.end_of_input(); ++t)
      if (expected.test(static_cast<std::size_t>(t))) items.push_back(describe_terminal(grammar_, t));
    constexpr std::size_t kShown = 10;
    std::string out;
    const std::size_t shown = std::min(items.size(), kShown);
    for (std::size_t i = 0; i < shown; ++i) {
      if (i > 0) out += (i + 1 == shown && items.size() <= kShown) ? " or " : ", ";
      out += items[i];
    }
    if (items.size() > kShown) out += " or " + std::to_string(items.size() - kShown) + " other terminals";
    return out;
  }

  void syntax_error(const TerminalSet& expected, SourcePosition start) {
    std::string message = look_.terminal == Token::kScanError
                              ? look_.error + "; expected " + expected_text(expected) + " here"
                              : "expected " + expected_text(expected) + ", found " + found_text();
    if (look_.terminal == grammar_.end_of_input())
      message += " (the sentence that starts at " + std::to_string(start.line) + ":" + std::to_string(start.column) +
                 " is not finished)";
    diagnostics_.error(look_.position, std::move(message));
  }

  // Skips to a token that can start a sentence, outside the brackets the
  // failed sentence opened; always moves on by at least one token when the
  // failed sentence read none, so that every round makes progress.
  void recover() {
    if (!consumed_ && look_.terminal != grammar_.end_of_input()) advance();
    const TerminalSet& starts = language_.parse.first[static_cast<std::size_t>(grammar_.start)];
    while (look_.terminal != grammar_.end_of_input()) {
      if (depth_ <= 0 && look_.terminal >= 0 && starts.test(static_cast<std::size_t>(look_.terminal))) return;
      advance();
    }
  }

  const Language& language_;
  const Grammar& grammar_;
  Scanner scanner_;
  SemanticHandler handler_;
  DiagnosticList& diagnostics_;
  Token look_;
  std::vector<StackEntry> stack_;
  long depth_ = 0;
  bool consumed_ = false;
};

}  // namespace

ScriptResult parse_script(const Language& language, std::string_view text) {
  ScriptResult result;
  DiagnosticList diagnostics;
  if (text.size() > kMaxScriptBytes) {
    diagnostics.error({1, 1}, "the script is " + std::to_string(text.size()) + " bytes; at most " +
                                  std::to_string(kMaxScriptBytes) + " are accepted: split it into several scripts");
    result.diagnostics = diagnostics.take();
    return result;
  }
  if (language.grammar.productions.empty()) {  // a default-constructed Language, not one load_language made
    diagnostics.error({1, 1}, "internal error: the language has no grammar");
    result.diagnostics = diagnostics.take();
    return result;
  }
  ScriptBuilder script;
  Driver driver(language, text, script, diagnostics);
  result.sentences = driver.run();
  result.meaning = std::move(script.meaning);
  result.diagnostics = diagnostics.take();
  return result;
}

}  // namespace fw::script
