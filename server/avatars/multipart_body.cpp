#include "multipart_body.hpp"

#include <algorithm>
#include <cctype>

namespace fw::server {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

/// The value of parameter `key` (e.g. `name`, `boundary`) in a header value
/// of `;`-separated parameters, unquoted; empty if it is not there.
std::string parameter(std::string_view header, std::string_view key) {
  std::size_t at = 0;
  while ((at = header.find(';', at)) != std::string_view::npos) {
    std::string_view rest = trim(header.substr(++at));
    if (lower(rest.substr(0, key.size())) != key || rest.substr(key.size(), 1) != "=") continue;
    rest.remove_prefix(key.size() + 1);
    if (!rest.empty() && rest.front() == '"') return std::string(rest.substr(1, rest.find('"', 1) - 1));
    return std::string(trim(rest.substr(0, rest.find(';'))));
  }
  return {};
}

/// One part's headers: its form name and content type.
bool read_part_headers(std::string_view headers, std::string& name, std::string& type) {
  std::size_t at = 0;
  while (at < headers.size()) {
    const std::size_t end = std::min(headers.find("\r\n", at), headers.size());
    const std::string_view line = headers.substr(at, end - at);
    at = end + 2;
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) return false;
    const std::string field = lower(trim(line.substr(0, colon)));
    const std::string_view value = trim(line.substr(colon + 1));
    if (field == "content-disposition") name = parameter(value, "name");
    if (field == "content-type") type = lower(trim(value.substr(0, value.find(';'))));
  }
  return !name.empty();
}

}  // namespace

std::string multipart_boundary(std::string_view content_type) {
  if (lower(trim(content_type.substr(0, content_type.find(';')))) != "multipart/form-data") return {};
  return parameter(content_type, "boundary");
}

bool read_multipart(std::span<const std::uint8_t> body, const std::string& boundary,
                    std::map<std::string, MultipartPart>& parts, std::string& error) {
  const std::string_view text(reinterpret_cast<const char*>(body.data()), body.size());
  const std::string delimiter = "--" + boundary;
  if (boundary.empty() || boundary.size() > 70 || text.substr(0, delimiter.size()) != delimiter) {
    error = "the multipart body does not start with its boundary";
    return false;
  }
  std::size_t at = delimiter.size();
  while (text.substr(at, 2) == "\r\n") {
    const std::size_t headers_end = text.find("\r\n\r\n", at + 2);
    const std::size_t next = text.find("\r\n" + delimiter, at);
    if (headers_end == std::string_view::npos || next == std::string_view::npos || headers_end > next) {
      error = "a part of the multipart body is cut off";
      return false;
    }
    std::string name, type;
    if (!read_part_headers(text.substr(at + 2, headers_end - at - 2), name, type)) {
      error = "a part of the multipart body has no form name (Content-Disposition: form-data; name=...)";
      return false;
    }
    if (parts.contains(name)) {
      error = "the multipart body has two parts named '" + name.substr(0, 32) + "'";
      return false;
    }
    parts[name] = {type, body.subspan(headers_end + 4, next - headers_end - 4)};
    at = next + 2 + delimiter.size();
  }
  if (text.substr(at, 2) != "--") {
    error = "the multipart body does not end with its closing boundary";
    return false;
  }
  return true;
}

}  // namespace fw::server
