#pragma once
// The chat lines a person at a terminal has `join` send (--chat): a file of
// timed lines, read whole before joining so that a mistake is said at once.
//
//   # a comment
//   2.5 hello everyone        sent 2.5 s after joining
//   how are you?              sent 2 s after the line before
//
// A line may start with the seconds after joining at which it is sent (a
// number, then a space); without one it follows the line before by
// kDefaultGapS. The text is sent as it stands (1 .. codec::kMaxChatBytes
// bytes); blank lines and lines starting with '#' are skipped.
#include <string>
#include <string_view>
#include <vector>

namespace fw::client {

struct ScriptedLine {
  double at_s = 0;  ///< seconds after the first welcome
  std::string text;
};

inline constexpr double kDefaultGapS = 2.0;
/// Limits on what a script may hold: it is read whole into memory.
inline constexpr std::size_t kMaxChatScriptBytes = 1 << 20;
inline constexpr std::size_t kMaxChatScriptLines = 10000;
inline constexpr double kMaxChatScriptSeconds = 1e6;

/// Parses `content`; false and `error` ("line N: ...", what to change) when
/// a line cannot be sent. The lines come out in the order they are sent.
bool parse_chat_script(std::string_view content, std::vector<ScriptedLine>& lines, std::string& error);

/// Reads and parses the file at `path`; false and `error` as above, or when
/// it cannot be read or is too large.
bool read_chat_script(const std::string& path, std::vector<ScriptedLine>& lines, std::string& error);

}  // namespace fw::client
