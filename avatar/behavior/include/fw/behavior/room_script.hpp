#pragma once
// A face script a person sends into a room (server/PROTOCOL.md 5.5, the FACS
// command): read with the shipped languages, held to a room's bounds, and
// turned into what it plays on the sender's face. A room plays at most one
// expression sentence (an AU track) and one vascular emotion (a colour
// episode) per script, and takes a few action-unit definitions: each
// redefines that unit on the sender's avatar, as a morph of the generic face
// (au_definition_morph.hpp) that the server measures with and every client
// rebuilds the avatar's face with (server/PROTOCOL.md 5.17). A definition
// with no displacements gives the unit back its shipped morph.
//
// The bounds keep one command's cost and effect small: the bytes bound the
// parse (linear in its input, face-script README "Limits"; the worst script
// of 4096 bytes reads in under 0.1 ms, room_script_timing_test.cpp),
// the counts and the length bound what a face is made to do.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/messages.hpp"
#include "fw/model/generic_face.hpp"
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
/// AU definitions one script may hold: a unit and its neighbours (the
/// paper's examples define one at a time).
inline constexpr std::size_t kMaxRoomScriptAuDefinitions = 4;
/// Action units one avatar may have redefined at once: the wire carries
/// both sides of each (codec::kMaxRedefinedChannels), and every client
/// keeps them beside the avatar's package.
inline constexpr std::size_t kMaxRedefinedUnitsPerAvatar = codec::kMaxRedefinedChannels / 2;
/// Displacements one definition may list (the paper's AU 1 has 14).
inline constexpr std::size_t kMaxRoomAuDisplacements = 64;
/// The largest displacement along any axis, in the definitions' units (a
/// face 200 wide): 40 is about 29 mm on an average face, more than a jaw
/// drops; a unit is not to tear a face apart.
inline constexpr double kMaxRoomAuDisplacement = 40.0;

/// A unit a script redefines: its generic morph per FaceParams channel (a
/// bilateral unit's two channels each get the morph's own side: vertices on
/// the person's left to the left channel, on the right to the right, the
/// midline shared half and half, so both at full strength make the whole
/// morph). No channels' morphs (`restore`): the shipped unit again.
struct UnitDefinition {
  int au = 0;
  bool restore = false;
  std::map<std::size_t, model::Morph> morphs;  ///< by channel; empty when restore
};
/// What a room plays of a script.
struct RoomScript {
  std::optional<script::KeyframeAnimation> animation;
  std::optional<script::VascularEmotion> emotion;
  std::vector<UnitDefinition> units;  ///< in the script's order; their previews are not played
};

/// Reads `text` into `out`. Returns "" when it can be played; else what was
/// wrong: a script error as "script LINE:COLUMN: message" (the first error,
/// position first so that a clipped answer keeps it), or the bound it passes
/// and what to do.
/// One AU definition held to a room's bounds and made into `out`; "" when it
/// can be used, else what was wrong and what to do.
std::string read_unit_definition(const script::AuDefinition& definition, const model::GenericFace& face,
                                 UnitDefinition& out);

/// AU definitions are made into morphs of `face` (the generic face).
std::string read_room_script(std::string_view text, RoomScript& out,
                             const model::GenericFace& face = model::generic_face());

}  // namespace fw::behavior
