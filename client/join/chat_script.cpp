#include "chat_script.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>

#include "fw/codec/messages.hpp"

namespace fw::client {
namespace {

// A leading "SECONDS " (digits with at most one '.'), or nothing.
bool leading_seconds(std::string_view line, double& seconds, std::size_t& text_at) {
  const std::size_t space = line.find(' ');
  if (space == 0 || space == std::string_view::npos) return false;
  const std::string_view number = line.substr(0, space);
  if (!std::all_of(number.begin(), number.end(), [](char c) { return (c >= '0' && c <= '9') || c == '.'; }))
    return false;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), seconds);
  if (ec != std::errc() || end != number.data() + number.size()) return false;
  text_at = line.find_first_not_of(' ', space);
  return true;
}

}  // namespace

bool parse_chat_script(std::string_view content, std::vector<ScriptedLine>& lines, std::string& error) {
  lines.clear();
  double last_s = -kDefaultGapS;
  std::size_t number = 0;
  while (!content.empty()) {
    const std::size_t end = content.find('\n');
    std::string_view line = content.substr(0, end);
    content = end == std::string_view::npos ? std::string_view{} : content.substr(end + 1);
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(" \t") == std::string_view::npos || line.front() == '#') continue;
    const std::string where = "line " + std::to_string(number) + ": ";
    double at_s = last_s + kDefaultGapS;
    std::size_t text_at = 0;
    if (leading_seconds(line, at_s, text_at)) {
      if (!(at_s >= 0 && at_s <= kMaxChatScriptSeconds)) {
        error = where + "the time must be 0 .. " + std::to_string(static_cast<long>(kMaxChatScriptSeconds)) + " seconds";
        return false;
      }
      if (text_at == std::string_view::npos) {
        error = where + "a time with no text after it";
        return false;
      }
      line = line.substr(text_at);
    }
    if (line.size() > codec::kMaxChatBytes) {
      error = where + "a chat line holds at most " + std::to_string(codec::kMaxChatBytes) + " bytes (this one " +
              std::to_string(line.size()) + "): split it";
      return false;
    }
    if (lines.size() >= kMaxChatScriptLines) {
      error = "more than " + std::to_string(kMaxChatScriptLines) + " lines: split the script";
      return false;
    }
    lines.push_back({at_s, std::string(line)});
    last_s = at_s;
  }
  // Sent in the order of their times; lines of one time keep the file's order.
  std::stable_sort(lines.begin(), lines.end(), [](const ScriptedLine& a, const ScriptedLine& b) { return a.at_s < b.at_s; });
  return true;
}

bool read_chat_script(const std::string& path, std::vector<ScriptedLine>& lines, std::string& error) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    error = "cannot read '" + path + "'";
    return false;
  }
  std::string content;
  content.resize(kMaxChatScriptBytes + 1);
  file.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(file.gcount()));
  if (content.size() > kMaxChatScriptBytes) {
    error = "'" + path + "' is larger than " + std::to_string(kMaxChatScriptBytes >> 20) + " MB: split the script";
    return false;
  }
  if (!parse_chat_script(content, lines, error)) {
    error = "'" + path + "', " + error;
    return false;
  }
  return true;
}

}  // namespace fw::client
