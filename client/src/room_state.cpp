#include "room_state.hpp"

#include <algorithm>

namespace fw::client {

std::vector<AvatarFace> RoomState::faces(std::chrono::steady_clock::time_point now) const {
  std::vector<AvatarFace> out;
  for (const auto& [id, avatar] : avatars) {
    const codec::Decoder* decoder_of_avatar = decoder.avatar(id);
    if (!decoder_of_avatar || decoder_of_avatar->frames_decoded() == 0) continue;
    const double seconds = std::chrono::duration<double>(now - avatar.last_frame_at).count();
    const auto ticks = static_cast<std::uint32_t>(std::clamp(seconds * tick_hz, 0.0, 1000.0));
    out.push_back({id, decoder_of_avatar->face(ticks)});
  }
  return out;
}

}  // namespace fw::client
