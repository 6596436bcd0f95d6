#pragma once
// A face script a person sends into a room (server/PROTOCOL.md 5.5, the FACS
// command): read with the shipped languages, held to a room's bounds, and
// turned into what it plays on the sender's face. A room plays at most one
// expression sentence (an AU track) and one vascular emotion (a colour
// episode) per script; action-unit definitions change the face model every
// client rebuilds faces from, so a room refuses them.
//
// The bounds keep one command's cost and effect small: the bytes bound the
// parse (linear in its input, face-script README "Limits"; the worst script
// of 4096 bytes reads in under 0.1 ms, room_script_timing_test.cpp),
// the counts and the length bound what a face is made to do.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "fw/codec/messages.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::behavior {

/// A script's bytes: the protocol's FACS command carries no more.
inline constexpr std::size_t kMaxRoomScriptBytes = codec::kMaxSentenceBytes;
/// Keyframes of its expression sentence: enough for any expression's rise,
/// peak and turns (the paper's anger has 2).
inline constexpr std::size_t kMaxRoomScriptKeyframes = 32;
/// The expression sentence's Animate and Hold steps together, in seconds
/// (0.1 s a step): a minute, as long as a person's look or snub is commonly
/// held; a face is not to be taken over for longer by one command.
inline constexpr double kMaxRoomScriptPlayS = 60.0;
/// Vascular expressions defined beside the emotion (the paper's blushing
/// uses 3; one per stage at most is of use, and stages are at most 32).
inline constexpr std::size_t kMaxRoomScriptVascularExpressions = 32;
/// A scripted vascular emotion's episode lasts this long: the median blush
/// (Shields, Mallory & Simon 1990, cited in vascular_episode.hpp); the
/// script's percentages divide it.
inline constexpr double kRoomScriptEpisodeS = 20.0;

/// What a room plays of a script.
struct RoomScript {
  std::optional<script::KeyframeAnimation> animation;
  std::optional<script::VascularEmotion> emotion;
};

/// Reads `text` into `out`. Returns "" when it can be played; else what was
/// wrong: a script error as "script LINE:COLUMN: message" (the first error,
/// position first so that a clipped answer keeps it), or the bound it passes
/// and what to do.
std::string read_room_script(std::string_view text, RoomScript& out);

}  // namespace fw::behavior
