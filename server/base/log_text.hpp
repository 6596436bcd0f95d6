#pragma once
// Text a peer chose (a request target, a header), made safe for a log
// line: bytes outside printable ASCII become '?', and it is cut short, so
// that nobody writes control characters or megabytes into the log.
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace fw::server {

inline std::string printable(std::string_view text, std::size_t most) {
  std::string out;
  out.reserve(std::min(text.size(), most) + 3);
  for (const char c : text.substr(0, most)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > most) out += "...";
  return out;
}

}  // namespace fw::server
