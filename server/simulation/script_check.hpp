#pragma once
// A face script checked for a person editing it (the face lab's "check",
// PROTOCOL.md 5.16): the same parser and grammar as `facewire-server script`
// and a room's FACS command, with the first error where it is, in words a
// command result carries (at most 120 bytes).
#include <string>
#include <string_view>
#include <vector>

namespace fw::server {

/// "" when `text` parses without errors and a room would play it; else
/// "line L, column C: what was wrong", with "(N more errors)" when there
/// are others, or what a room refuses of a well-formed script (a bound it
/// passes: room_script.hpp), as playing it would answer.
std::string check_script(std::string_view text);

/// What a room would play of `text` (a saved look, PROTOCOL.md 8.2): "" and
/// what it holds in `kinds` ("expression", "vascular", "definitions", in
/// that order) when a room plays it; else what playing it would answer (a
/// script error as "script LINE:COLUMN: message", or the bound it passes).
std::string playable_script(std::string_view text, std::vector<std::string>& kinds);

}  // namespace fw::server
