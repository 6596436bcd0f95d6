#pragma once
// Errors and warnings about a script, tied to where in the text they are.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fw::script {

/// A place in a script: line and column both count from 1; columns count
/// bytes, so a tab is one column.
struct SourcePosition {
  int line = 1;
  int column = 1;
  friend bool operator==(const SourcePosition&, const SourcePosition&) = default;
};

enum class Severity : unsigned char { error, warning };

/// One message for a person: what is wrong and, where it helps, what to do.
struct Diagnostic {
  Severity severity = Severity::error;
  SourcePosition position;
  std::string message;
};

/// The diagnostics of one parse, bounded: after kMaxErrors errors one last
/// error says that the parse stopped, and later errors are counted but not
/// kept (the parser stops once full() holds); warnings beyond kMaxWarnings
/// are dropped.
class DiagnosticList {
 public:
  void error(SourcePosition position, std::string message);
  void warning(SourcePosition position, std::string message);

  /// Errors reported so far, including those not kept.
  std::size_t error_count() const { return error_count_; }
  /// True once the error limit is reached: the parser stops.
  bool full() const;
  const std::vector<Diagnostic>& items() const { return items_; }
  std::vector<Diagnostic> take() { return std::move(items_); }

 private:
  std::vector<Diagnostic> items_;
  std::size_t error_count_ = 0;
  std::size_t warning_count_ = 0;
};

/// `FILE:LINE:COLUMN: message`, or `FILE:LINE:COLUMN: warning: message`.
std::string format_diagnostic(std::string_view file, const Diagnostic& diagnostic);

/// `text` made safe to quote in a message: bytes outside printable ASCII as
/// \xNN, cut to `max_bytes` with "..." appended when longer.
std::string printable(std::string_view text, std::size_t max_bytes = 40);

/// `value` in the shortest form that reads back the same ("2.5", "10", "1e+20").
std::string number_text(double value);

}  // namespace fw::script
