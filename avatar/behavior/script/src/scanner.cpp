#include "fw/script/scanner.hpp"

#include <charconv>
#include <cmath>

#include "fw/script/limits.hpp"
#include "word_chars.hpp"

namespace fw::script {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// from_chars takes no leading '+'.
std::string_view without_plus(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  return text;
}

std::string unknown_word(std::string_view word) {
  std::string message(1, '\'');
  message.append(printable(word)).append("' is not a word of this language");
  return message;
}

}  // namespace

Scanner::Scanner(const ScanTable& table, std::string_view text) : table_(table), text_(text) {
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") offset_ = 3;
}

void Scanner::advance_to(std::size_t offset) {
  for (; offset_ < offset; ++offset_) {
    if (text_[offset_] == '\n') {
      ++position_.line;
      position_.column = 1;
    } else {
      ++position_.column;
    }
  }
}

Token Scanner::error_token(std::size_t begin, std::size_t end, std::string message) {
  Token token;
  token.terminal = Token::kScanError;
  token.lexeme = text_.substr(begin, end - begin);
  token.position = position_;
  token.error = std::move(message);
  advance_to(end);
  return token;
}

Token Scanner::data_token(int terminal, std::size_t begin, std::size_t end) {
  Token token;
  token.terminal = terminal;
  token.lexeme = text_.substr(begin, end - begin);
  token.position = position_;
  const std::string_view lexeme = token.lexeme;
  switch (table_.terminal_kinds[static_cast<std::size_t>(terminal)]) {
    case TerminalKind::keyword:
    case TerminalKind::symbol: break;
    case TerminalKind::integer: {
      const std::string_view digits = without_plus(lexeme);
      std::int64_t v = 0;
      const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (ec != std::errc() || ptr != digits.data() + digits.size())
        return error_token(begin, end, "the integer " + printable(lexeme) + " is too large");
      token.value = SemanticValue::of_integer(v, position_);
      break;
    }
    case TerminalKind::real: {
      const std::string_view digits = without_plus(lexeme);
      double v = 0;
      const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (ec != std::errc() || ptr != digits.data() + digits.size() || !std::isfinite(v))
        return error_token(begin, end, "the number " + printable(lexeme) + " is out of range");
      token.value = SemanticValue::of_real(v, position_);
      break;
    }
    case TerminalKind::string: {
      std::string v;
      for (std::size_t i = 1; i + 1 < lexeme.size(); ++i) {
        if (lexeme[i] == '\\') ++i;  // the table only lets \" and \\ through
        v += lexeme[i];
      }
      token.value = SemanticValue::of_text(std::move(v), position_);
      break;
    }
    case TerminalKind::identifier: token.value = SemanticValue::of_text(std::string(lexeme), position_); break;
  }
  advance_to(end);
  return token;
}

Token Scanner::next() {
  for (;;) {
    if (offset_ >= text_.size()) {
      Token end;
      end.terminal = table_.end_of_input;
      end.position = position_;
      return end;
    }
    const std::size_t begin = offset_;
    std::size_t at = begin, last_end = begin;
    std::int16_t last_accept = ScanTable::kAcceptNothing;
    int state = 0;
    bool too_long = false;
    while (at < text_.size()) {
      const std::int16_t following = table_.step(state, static_cast<unsigned char>(text_[at]));
      if (following == ScanTable::kNoState) break;
      state = following;
      ++at;
      const std::int16_t accept = table_.accept[static_cast<std::size_t>(state)];
      if (accept != ScanTable::kAcceptNothing) {
        last_accept = accept;
        last_end = at;
      }
      // Comments and white space may run on; anything else is cut off here,
      // which also bounds the backtracking of the longest match.
      if (at - begin > kMaxTokenBytes && accept != ScanTable::kAcceptSkip) {
        too_long = true;
        break;
      }
    }
    if (too_long) {
      std::size_t end = at;
      while (end < text_.size() && !is_space(text_[end])) ++end;
      return error_token(begin, end,
                         "a word, number or string longer than " + std::to_string(kMaxTokenBytes) +
                             " characters starts here; shorten it");
    }
    if (last_accept == ScanTable::kAcceptSkip) {
      advance_to(last_end);
      continue;
    }
    if (last_accept >= 0) return data_token(last_accept, begin, last_end);

    if (last_accept == ScanTable::kAcceptUnknownWord)
      return error_token(begin, last_end, unknown_word(text_.substr(begin, last_end - begin)));
    const char c = text_[begin];
    std::size_t end = begin + 1;
    if (is_word_char(c)) {
      while (end < text_.size() && is_word_char(text_[end])) ++end;
      return error_token(begin, end, unknown_word(text_.substr(begin, end - begin)));
    }
    if (c == '"') {
      while (end < text_.size() && text_[end] != '\n' && end - begin < kMaxTokenBytes) ++end;
      return error_token(begin, end,
                         "this string is not closed on its line, or holds an escape other than \\\" and \\\\");
    }
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x80) {
      while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xC0) == 0x80) ++end;
      return error_token(begin, end,
                         "unexpected character " + printable(text_.substr(begin, end - begin)) +
                             " (outside strings a script is plain ASCII)");
    }
    return error_token(begin, end, "unexpected character '" + printable(text_.substr(begin, 1)) + "'");
  }
}

}  // namespace fw::script
