// Room frames and resync requests (FORMAT.md, "Room frames", "Resync requests").
#include <algorithm>
#include <cassert>

#include "frame_writer.hpp"
#include "fw/codec/byte_reader.hpp"
#include "fw/codec/byte_writer.hpp"

namespace fw::codec {
namespace {

// First-byte checks shared by the byte-aligned messages.
DecodeError check_first_byte(std::uint8_t first, FrameType expected) {
  if ((first >> 4) != kFormatVersion) return DecodeError::unsupported_version;
  if ((first & 0x0F) > static_cast<std::uint8_t>(FrameType::resync_request)) return DecodeError::unknown_frame_type;
  if ((first & 0x0F) != static_cast<std::uint8_t>(expected)) return DecodeError::wrong_frame_type;
  return DecodeError::ok;
}

constexpr std::size_t kAvatarIdVarintBytes = 3;   // kMaxAvatarId < 2^21
constexpr std::size_t kEntryHeadVarintBytes = 4;  // avatar id * 2 + 1 < 2^22
constexpr std::size_t kLengthVarintBytes = 2;    // kMaxFrameBytes < 2^14

}  // namespace

void write_room_frame(std::span<const RoomEntry> entries, std::vector<std::uint8_t>& out) {
  assert(!entries.empty() && entries.size() <= kMaxRoomAvatars);
  ByteWriter w(out);
  w.u8(first_byte(FrameType::room));
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const RoomEntry& e = entries[i];
    assert(e.avatar_id <= kMaxAvatarId);
    assert(!e.frame.empty() && e.frame.size() <= kMaxFrameBytes);
    // One varint says who and whether more entries follow; the last frame
    // runs to the end of the message, so only the others carry a length.
    const bool more = i + 1 < entries.size();
    w.varint((e.avatar_id << 1) | (more ? 1u : 0u));
    if (more) w.varint(static_cast<std::uint32_t>(e.frame.size()));
    w.bytes(e.frame);
  }
}

DecodeError read_room_frame(std::span<const std::uint8_t> bytes, std::vector<RoomEntry>& entries) {
  entries.clear();
  if (bytes.empty()) return DecodeError::empty_frame;
  if (bytes.size() > kMaxRoomFrameBytes) return DecodeError::frame_too_large;
  ByteReader r(bytes);
  if (const DecodeError e = check_first_byte(r.u8(), FrameType::room); e != DecodeError::ok) return e;
  bool more = true;
  while (more) {
    if (entries.size() == kMaxRoomAvatars) return DecodeError::too_many_avatars;
    const std::uint32_t head = r.varint(kEntryHeadVarintBytes);
    if (r.failed()) return DecodeError::truncated;
    const std::uint32_t id = head >> 1;
    more = (head & 1u) != 0;
    if (id > kMaxAvatarId) return DecodeError::value_out_of_range;
    std::size_t length = r.remaining();
    if (more) {
      length = r.varint(kLengthVarintBytes);
      if (r.failed()) return DecodeError::truncated;
    }
    if (length == 0) return DecodeError::empty_frame;
    if (length > kMaxFrameBytes) return DecodeError::frame_too_large;
    const auto frame = r.bytes(length);
    if (r.failed()) return DecodeError::truncated;
    const bool duplicate =
        std::any_of(entries.begin(), entries.end(), [id](const RoomEntry& e) { return e.avatar_id == id; });
    if (duplicate) return DecodeError::duplicate_avatar;
    entries.push_back({id, frame});
  }
  return DecodeError::ok;
}

void write_resync_request(std::span<const std::uint32_t> avatar_ids, std::vector<std::uint8_t>& out) {
  assert(avatar_ids.size() <= kMaxRoomAvatars);
  ByteWriter w(out);
  w.u8(first_byte(FrameType::resync_request));
  w.varint(static_cast<std::uint32_t>(avatar_ids.size()));
  for (const std::uint32_t id : avatar_ids) {
    assert(id <= kMaxAvatarId);
    w.varint(id);
  }
}

DecodeError read_resync_request(std::span<const std::uint8_t> bytes, std::vector<std::uint32_t>& avatar_ids) {
  avatar_ids.clear();
  if (bytes.empty()) return DecodeError::empty_frame;
  ByteReader r(bytes);
  if (const DecodeError e = check_first_byte(r.u8(), FrameType::resync_request); e != DecodeError::ok) return e;
  const std::uint32_t count = r.varint(2);
  if (r.failed()) return DecodeError::truncated;
  if (count > kMaxRoomAvatars) return DecodeError::too_many_avatars;
  avatar_ids.reserve(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t id = r.varint(kAvatarIdVarintBytes);
    if (r.failed()) return DecodeError::truncated;
    if (id > kMaxAvatarId) return DecodeError::value_out_of_range;
    avatar_ids.push_back(id);
  }
  if (r.remaining() != 0) return DecodeError::trailing_bytes;
  return DecodeError::ok;
}

}  // namespace fw::codec
