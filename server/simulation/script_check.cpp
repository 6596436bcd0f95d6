#include "script_check.hpp"

#include "fw/behavior/room_script.hpp"
#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"

namespace fw::server {

std::string check_script(std::string_view text) {
  const script::ScriptResult result = script::parse_script(script::default_language(), text);
  const script::Diagnostic* first = nullptr;
  std::size_t errors = 0;
  for (const script::Diagnostic& d : result.diagnostics) {
    if (d.severity != script::Severity::error) continue;
    if (!first) first = &d;
    ++errors;
  }
  if (!first) {
    if (result.sentences == 0) return "line 1, column 1: the script holds no sentence";
    // Well formed: what a room would still refuse of it (its bounds, what
    // it does not play), as playing it would answer.
    behavior::RoomScript playable;
    return behavior::read_room_script(text, playable);
  }
  // The count goes first: the message may be cut to fit a command result.
  std::string out = "line " + std::to_string(first->position.line) + ", column " +
                    std::to_string(first->position.column) + ": ";
  if (errors > 1) out += "(" + std::to_string(errors - 1) + " more errors) ";
  return out + first->message;
}

std::string playable_script(std::string_view text, std::vector<std::string>& kinds) {
  kinds.clear();
  behavior::RoomScript read;
  if (std::string error = behavior::read_room_script(text, read); !error.empty()) return error;
  if (read.animation) kinds.push_back("expression");
  if (read.emotion) kinds.push_back("vascular");
  if (!read.units.empty()) kinds.push_back("definitions");
  return {};
}

}  // namespace fw::server
