#include "fw/script/diagnostic.hpp"

#include <charconv>

#include "fw/script/limits.hpp"

namespace fw::script {

void DiagnosticList::error(SourcePosition position, std::string message) {
  ++error_count_;
  if (error_count_ < kMaxErrors) {
    items_.push_back({Severity::error, position, std::move(message)});
  } else if (error_count_ == kMaxErrors) {
    items_.push_back({Severity::error, position,
                      "too many errors (" + std::to_string(kMaxErrors) + "); stopping here: fix these and run again"});
  }
}

void DiagnosticList::warning(SourcePosition position, std::string message) {
  if (warning_count_ >= kMaxWarnings) return;
  ++warning_count_;
  items_.push_back({Severity::warning, position, std::move(message)});
}

bool DiagnosticList::full() const { return error_count_ >= kMaxErrors; }

std::string format_diagnostic(std::string_view file, const Diagnostic& diagnostic) {
  std::string out(file);
  out += ':' + std::to_string(diagnostic.position.line) + ':' + std::to_string(diagnostic.position.column) + ": ";
  if (diagnostic.severity == Severity::warning) out += "warning: ";
  out += diagnostic.message;
  return out;
}

std::string printable(std::string_view text, std::size_t max_bytes) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (i == max_bytes) {
      out += "...";
      break;
    }
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += static_cast<char>(byte);
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

std::string number_text(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

}  // namespace fw::script
