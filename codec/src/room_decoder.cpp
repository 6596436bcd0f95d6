// RoomDecoder: one Decoder per avatar of a room stream, created on the
// avatar's first frame and bounded by kMaxRoomAvatars.
#include <algorithm>

#include "fw/codec/codec.hpp"

namespace fw::codec {

RoomDecoder::RoomDecoder(const StreamOptions& options) : options_(options) {}

RoomDecoder::Result RoomDecoder::decode(std::span<const std::uint8_t> room_frame) {
  Result result;
  std::vector<RoomEntry> entries;
  result.error = read_room_frame(room_frame, entries);
  if (result.error != DecodeError::ok) return result;
  result.avatars.reserve(entries.size());
  for (const RoomEntry& entry : entries) {
    auto it = std::find_if(decoders_.begin(), decoders_.end(),
                           [&](const auto& d) { return d.first == entry.avatar_id; });
    if (it == decoders_.end()) {
      if (decoders_.size() >= kMaxRoomAvatars) {
        result.avatars.emplace_back(entry.avatar_id, DecodeError::too_many_avatars);
        continue;
      }
      decoders_.emplace_back(entry.avatar_id, Decoder(options_));
      it = decoders_.end() - 1;
    }
    result.avatars.emplace_back(entry.avatar_id, it->second.decode(entry.frame));
  }
  return result;
}

const Decoder* RoomDecoder::avatar(std::uint32_t avatar_id) const {
  const auto it =
      std::find_if(decoders_.begin(), decoders_.end(), [&](const auto& d) { return d.first == avatar_id; });
  return it == decoders_.end() ? nullptr : &it->second;
}

void RoomDecoder::remove(std::uint32_t avatar_id) {
  std::erase_if(decoders_, [&](const auto& d) { return d.first == avatar_id; });
}

std::vector<std::uint32_t> RoomDecoder::needing_key_frames() const {
  std::vector<std::uint32_t> ids;
  for (const auto& [id, decoder] : decoders_)
    if (decoder.needs_key_frame()) ids.push_back(id);
  return ids;
}

}  // namespace fw::codec
