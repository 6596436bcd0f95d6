#pragma once
// Saved looks (PROTOCOL.md 8.2): face scripts an avatar's owner keeps with
// the avatar under names of their own, to play again in any room (command
// kind 6). Here what a look is, its bounds, and the file that holds an
// avatar's looks on disk; look_store.hpp keeps them.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/messages.hpp"

namespace fw::server {

struct SavedLook {
  std::string name;    ///< NFC, visible, 1 .. kMaxLookNameBytes bytes
  std::string script;  ///< a face script a room plays (checked when saved)
  bool operator==(const SavedLook&) const = default;
};

/// Looks one avatar keeps: a handful of expressions, an episode or two and
/// some definitions, as a picker shows them without scrolling.
inline constexpr std::size_t kMaxLooksPerAvatar = 16;
/// A look's script: what a FACS command carries (PROTOCOL.md 5.5).
inline constexpr std::size_t kMaxLookScriptBytes = codec::kMaxSentenceBytes;
/// A look's name: what a play-look command carries.
inline constexpr std::size_t kMaxLookNameBytes = codec::kMaxLookNameBytes;

/// `name` in NFC in `normalized`, and an empty result; else why it cannot
/// name a look, for the person who chose it (the rules of display names:
/// no controls, no invisible characters, at least one visible one).
std::string normalize_look_name(std::string_view name, std::string& normalized);

/// An avatar's looks as its file holds them: a header line, then for each
/// look "NAME_BYTES SCRIPT_BYTES\n", the name, the script and "\n".
std::string encode_looks(const std::vector<SavedLook>& looks);
/// The looks of such a file; false (and `looks` empty) when it is not one
/// (cut short by a full disk, written by something else).
bool decode_looks(std::string_view bytes, std::vector<SavedLook>& looks);

}  // namespace fw::server
