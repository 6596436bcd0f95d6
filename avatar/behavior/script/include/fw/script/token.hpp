#pragma once
// What the scanner driver hands the parser driver.
#include <string>
#include <string_view>

#include "fw/script/diagnostic.hpp"
#include "fw/script/semantic_value.hpp"

namespace fw::script {

struct Token {
  static constexpr int kScanError = -1;

  /// Terminal index in the grammar, Grammar::end_of_input() at the end, or
  /// kScanError for text that is no token of the language.
  int terminal = kScanError;
  std::string_view lexeme;  ///< the text as written (a view into the script)
  SemanticValue value;      ///< integer, real or text for data terminals; none otherwise
  SourcePosition position;  ///< of the first byte
  std::string error;        ///< for kScanError: what is wrong with the text
};

}  // namespace fw::script
