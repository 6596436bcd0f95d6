#pragma once
// The scanner driver: one fixed loop that runs any scan table over a script
// and hands out tokens. It never fails: text that is no token becomes a
// Token::kScanError token with a message, and scanning goes on after it.
#include <cstddef>
#include <string_view>

#include "fw/script/scan_table.hpp"
#include "fw/script/token.hpp"

namespace fw::script {

class Scanner {
 public:
  /// `table` and `text` must outlive the scanner. A UTF-8 byte-order mark at
  /// the start is skipped.
  Scanner(const ScanTable& table, std::string_view text);

  /// The next token; at the end, a token of table.end_of_input (again on
  /// every later call). Tokens of more than kMaxTokenBytes bytes are errors;
  /// comments and white space may be of any length.
  Token next();

 private:
  Token error_token(std::size_t begin, std::size_t end, std::string message);
  Token data_token(int terminal, std::size_t begin, std::size_t end);
  void advance_to(std::size_t offset);

  const ScanTable& table_;
  std::string_view text_;
  std::size_t offset_ = 0;
  SourcePosition position_;
};

}  // namespace fw::script
