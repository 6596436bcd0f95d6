#pragma once
// The byte layout of scene files (codec/FORMAT.md, "Appendix A. Scene
// files"), shared by their writer (scene_file_write.cpp), their reader
// (scene_file_read.cpp) and the file level (scene_file.cpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fw/behavior/scene_file.hpp"
#include "fw/codec/byte_reader.hpp"
#include "fw/codec/codec.hpp"

namespace fw::behavior::scene_layout {

// "FWSCENE" then the version as an ASCII digit.
inline constexpr std::array<std::uint8_t, 7> kMagicStem = {'F', 'W', 'S', 'C', 'E', 'N', 'E'};
inline constexpr std::size_t kMagicBytes = kMagicStem.size() + 1;
inline constexpr int kOldestVersion = 1;
inline constexpr int kNewestVersion = 3;
// Version 3 stores the corrective weights: FaceParams schema 2, 53 channels.
// Versions 1 and 2 hold schema 1's 47 (no correctives: they read as 0).
inline constexpr int kFirstCorrectiveVersion = 3;
inline constexpr std::uint16_t kSchemaBeforeCorrectives = 1;
inline constexpr std::size_t kChannelsBeforeCorrectives = codec::kChannelCount - codec::kCorrectiveCount;
inline constexpr std::uint16_t schema_of(int version) {
  return version >= kFirstCorrectiveVersion ? codec::kFaceParamsSchema : kSchemaBeforeCorrectives;
}
inline constexpr std::size_t channels_of(int version) {
  return version >= kFirstCorrectiveVersion ? codec::kChannelCount : kChannelsBeforeCorrectives;
}

// Magic, schema, channels, fps, avatars (u16 each after the magic), ticks (u32).
inline constexpr std::size_t kHeaderBytesV1 = kMagicBytes + 4 * 2 + 4;
inline constexpr std::size_t kHeaderBytesV2 = kHeaderBytesV1 + 4;  // + u32 events
// Flags and name length; the name follows.
inline constexpr std::size_t kAvatarFixedBytes = 2;
// Version 2: u32 joined, u32 left, then the seat as four float32.
inline constexpr std::size_t kPresenceBytes = 2 * 4;
inline constexpr std::size_t kSeatBytes = 4 * 4;
inline constexpr std::size_t face_bytes(int version) { return channels_of(version) * 4; }
inline constexpr std::size_t kMaxFaceBytes = face_bytes(kNewestVersion);
// u32 tick, u16 avatar, u8 text length; the text follows.
inline constexpr std::size_t kEventFixedBytes = 4 + 2 + 1;

// Avatar flags: bit 0 is idle; the other bits are 0 in every version.
inline constexpr std::uint8_t kFlagIdle = 0x01;

// The largest file the limits allow (about 1.3 GB): a reader refuses a
// larger one before reading it.
inline constexpr std::uint64_t kMaxFileBytes =
    kHeaderBytesV2 + kMaxSceneAvatars * (kAvatarFixedBytes + kMaxSceneNameBytes + kPresenceBytes + kSeatBytes) +
    std::uint64_t{kMaxSceneTicks} * kMaxSceneAvatars * kMaxFaceBytes +
    std::uint64_t{kMaxSceneEvents} * (kEventFixedBytes + kMaxSceneEventBytes);

// The limits, for error messages.
inline std::string limits_text() {
  return "(1-" + std::to_string(kMaxSceneAvatars) + " avatars, 1-" + std::to_string(kMaxSceneTicks) + " ticks, 1-" +
         std::to_string(kMaxSceneFps) + " fps, at most " + std::to_string(kMaxSceneEvents) + " events)";
}

// When an avatar is in a scene of `ticks` ticks: it joins at one of its
// ticks and leaves after that, at the latest at its end, or stays.
inline bool presence_fits(const SceneAvatar& avatar, std::size_t ticks) {
  if (avatar.joined_tick >= ticks) return false;
  return avatar.left_tick == kPresentToTheEnd || (avatar.left_tick > avatar.joined_tick && avatar.left_tick <= ticks);
}

// Reads the magic at the reader's position: the version (1 .. 3), or 0 with
// `error` saying why the bytes are not a scene this build reads. The file
// level checks it before reading a whole file; the parser starts with it.
int read_magic(codec::ByteReader& in, std::string& error);

}  // namespace fw::behavior::scene_layout
