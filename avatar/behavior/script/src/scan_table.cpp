#include "fw/script/scan_table.hpp"

#include <algorithm>
#include <bitset>
#include <cctype>
#include <climits>
#include <map>
#include <unordered_set>

#include "fw/script/limits.hpp"

namespace fw::script {
namespace {

using ByteSet = std::bitset<256>;

ByteSet bytes_where(bool (*predicate)(unsigned char)) {
  ByteSet set;
  for (unsigned b = 0; b < 256; ++b)
    if (predicate(static_cast<unsigned char>(b))) set.set(b);
  return set;
}

ByteSet one_of(std::string_view chars) {
  ByteSet set;
  for (char c : chars) set.set(static_cast<unsigned char>(c));
  return set;
}

// Equal-length ties go to the lowest number.
enum Priority : int { kLiteral = 0, kSkip = 1, kInteger = 2, kReal = 3, kString = 4, kIdentifier = 5, kUnknownWord = 6 };

struct NfaState {
  std::vector<std::pair<ByteSet, int>> edges;
  std::int16_t accept = ScanTable::kAcceptNothing;
  int priority = INT_MAX;
};

class Nfa {
 public:
  Nfa() { states_.emplace_back(); }  // state 0 starts every pattern

  int add_state() {
    states_.emplace_back();
    return static_cast<int>(states_.size()) - 1;
  }
  void edge(int from, const ByteSet& on, int to) { states_[static_cast<std::size_t>(from)].edges.emplace_back(on, to); }
  void accept(int state, std::int16_t what, int priority) {
    NfaState& s = states_[static_cast<std::size_t>(state)];
    if (priority < s.priority) {
      s.accept = what;
      s.priority = priority;
    }
  }
  /// A chain from the start spelling `text`; returns its last state.
  int literal(std::string_view text, bool ignore_case) {
    int at = 0;
    for (char c : text) {
      const int to = add_state();
      ByteSet on = one_of(std::string(1, c));
      if (ignore_case) {
        on.set(static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(c))));
        on.set(static_cast<unsigned char>(std::toupper(static_cast<unsigned char>(c))));
      }
      edge(at, on, to);
      at = to;
    }
    return at;
  }
  const std::vector<NfaState>& states() const { return states_; }

 private:
  std::vector<NfaState> states_;
};

bool is_digit(unsigned char b) { return b >= '0' && b <= '9'; }
bool is_word_start(unsigned char b) { return (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || b == '_'; }
bool is_word_char(unsigned char b) { return is_word_start(b) || is_digit(b); }
bool is_space(unsigned char b) { return b == ' ' || b == '\t' || b == '\r' || b == '\n' || b == '\f' || b == '\v'; }
bool is_not_newline(unsigned char b) { return b != '\n'; }
bool is_string_body(unsigned char b) { return b != '"' && b != '\\' && b != '\n' && b != '\r'; }

void add_word(Nfa& nfa, std::int16_t accept, int priority) {
  const int word = nfa.add_state();
  nfa.edge(0, bytes_where(is_word_start), word);
  nfa.edge(word, bytes_where(is_word_char), word);
  nfa.accept(word, accept, priority);
}

void add_integer(Nfa& nfa, std::int16_t accept) {
  const ByteSet digit = bytes_where(is_digit);
  const int sign = nfa.add_state(), digits = nfa.add_state();
  nfa.edge(0, one_of("+-"), sign);
  nfa.edge(0, digit, digits);
  nfa.edge(sign, digit, digits);
  nfa.edge(digits, digit, digits);
  nfa.accept(digits, accept, kInteger);
}

// [+-]? digits ( . digits )? ( [eE] [+-]? digits )?, where the fraction or
// the exponent is required when integers are a terminal of their own.
void add_real(Nfa& nfa, std::int16_t accept, bool integers_too) {
  const ByteSet digit = bytes_where(is_digit);
  const int sign = nfa.add_state(), whole = nfa.add_state(), dot = nfa.add_state(), fraction = nfa.add_state(),
            e = nfa.add_state(), e_sign = nfa.add_state(), exponent = nfa.add_state();
  nfa.edge(0, one_of("+-"), sign);
  nfa.edge(0, digit, whole);
  nfa.edge(sign, digit, whole);
  nfa.edge(whole, digit, whole);
  nfa.edge(whole, one_of("."), dot);
  nfa.edge(dot, digit, fraction);
  nfa.edge(fraction, digit, fraction);
  nfa.edge(whole, one_of("eE"), e);
  nfa.edge(fraction, one_of("eE"), e);
  nfa.edge(e, one_of("+-"), e_sign);
  nfa.edge(e, digit, exponent);
  nfa.edge(e_sign, digit, exponent);
  nfa.edge(exponent, digit, exponent);
  nfa.accept(fraction, accept, kReal);
  nfa.accept(exponent, accept, kReal);
  if (integers_too) nfa.accept(whole, accept, kReal);
}

void add_string(Nfa& nfa, std::int16_t accept) {
  const int body = nfa.add_state(), escape = nfa.add_state(), closed = nfa.add_state();
  nfa.edge(0, one_of("\""), body);
  nfa.edge(body, bytes_where(is_string_body), body);
  nfa.edge(body, one_of("\\"), escape);
  nfa.edge(escape, one_of("\"\\"), body);
  nfa.edge(body, one_of("\""), closed);
  nfa.accept(closed, accept, kString);
}

void add_skips(Nfa& nfa, const ScannerOptions& options) {
  const int space = nfa.add_state();
  nfa.edge(0, bytes_where(is_space), space);
  nfa.edge(space, bytes_where(is_space), space);
  nfa.accept(space, ScanTable::kAcceptSkip, kSkip);
  for (const std::string& introducer : options.comment_introducers) {
    const int comment = nfa.literal(introducer, false);
    nfa.edge(comment, bytes_where(is_not_newline), comment);
    nfa.accept(comment, ScanTable::kAcceptSkip, kSkip);
  }
}

// Bytes that every edge treats alike share one class, so the table has a
// column per class rather than per byte.
int compute_byte_classes(const Nfa& nfa, std::array<std::uint8_t, 256>& byte_class) {
  std::array<int, 256> cls{};
  int count = 1;
  std::unordered_set<ByteSet> seen;
  for (const NfaState& state : nfa.states()) {
    for (const auto& [on, to] : state.edges) {
      if (!seen.insert(on).second) continue;
      std::map<std::pair<int, bool>, int> renumber;
      for (unsigned b = 0; b < 256; ++b)
        cls[b] = renumber.emplace(std::pair{cls[b], on.test(b)}, static_cast<int>(renumber.size())).first->second;
      count = static_cast<int>(renumber.size());
    }
  }
  for (unsigned b = 0; b < 256; ++b) byte_class[b] = static_cast<std::uint8_t>(cls[b]);
  return count;
}

}  // namespace

bool build_scan_table(const Grammar& grammar, ScanTable& table, std::string& error) {
  Nfa nfa;
  bool has_identifier = false, has_integer = false;
  for (const Terminal& t : grammar.terminals) {
    has_identifier |= t.kind == TerminalKind::identifier;
    has_integer |= t.kind == TerminalKind::integer;
  }
  for (std::size_t i = 0; i < grammar.terminals.size(); ++i) {
    const Terminal& t = grammar.terminals[i];
    const auto index = static_cast<std::int16_t>(i);
    switch (t.kind) {
      case TerminalKind::keyword:
        nfa.accept(nfa.literal(t.spelling, grammar.scanner.keywords_ignore_case), index, kLiteral);
        break;
      case TerminalKind::symbol: nfa.accept(nfa.literal(t.spelling, false), index, kLiteral); break;
      case TerminalKind::integer: add_integer(nfa, index); break;
      case TerminalKind::real: add_real(nfa, index, !has_integer); break;
      case TerminalKind::string: add_string(nfa, index); break;
      case TerminalKind::identifier: add_word(nfa, index, kIdentifier); break;
    }
  }
  // Without identifiers a word such as "Animate2" must still be read whole,
  // to be reported as an unknown word rather than split into "Animate" "2".
  if (!has_identifier) add_word(nfa, ScanTable::kAcceptUnknownWord, kUnknownWord);
  add_skips(nfa, grammar.scanner);

  ScanTable out;
  out.class_count = compute_byte_classes(nfa, out.byte_class);
  std::array<unsigned, 256> representative{};
  for (unsigned b = 256; b-- > 0;) representative[out.byte_class[b]] = b;

  // Subset construction: each DFA state is a set of NFA states.
  std::map<std::vector<int>, int> ids;
  std::vector<std::vector<int>> sets;
  const auto state_of = [&](std::vector<int> set) -> int {
    const auto [at, fresh] = ids.emplace(set, static_cast<int>(sets.size()));
    if (fresh) sets.push_back(std::move(set));
    return at->second;
  };
  state_of({0});
  for (std::size_t s = 0; s < sets.size(); ++s) {
    if (sets.size() > kMaxScanStates) {
      error = "the terminals need more than " + std::to_string(kMaxScanStates) +
              " scanner states; use fewer or shorter keywords and symbols";
      return false;
    }
    std::int16_t accept = ScanTable::kAcceptNothing;
    int priority = INT_MAX;
    for (int n : sets[s]) {
      const NfaState& state = nfa.states()[static_cast<std::size_t>(n)];
      if (state.priority < priority) {
        priority = state.priority;
        accept = state.accept;
      }
    }
    out.accept.push_back(accept);
    for (int c = 0; c < out.class_count; ++c) {
      std::vector<int> target;
      for (int n : sets[s])
        for (const auto& [on, to] : nfa.states()[static_cast<std::size_t>(n)].edges)
          if (on.test(representative[static_cast<std::size_t>(c)])) target.push_back(to);
      std::sort(target.begin(), target.end());
      target.erase(std::unique(target.begin(), target.end()), target.end());
      out.next.push_back(target.empty() ? ScanTable::kNoState : static_cast<std::int16_t>(state_of(std::move(target))));
    }
  }
  for (const Terminal& t : grammar.terminals) out.terminal_kinds.push_back(t.kind);
  out.end_of_input = grammar.end_of_input();
  table = std::move(out);
  return true;
}

}  // namespace fw::script
