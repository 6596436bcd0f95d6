#include "room_members.hpp"

#include <functional>

#include <spdlog/spdlog.h>

namespace fw::server {

StoredAvatar stored_face_of(AvatarStore& store, const codec::AvatarInfo& info, const std::string& room) {
  if (auto stored = store.get(info.asset)) return *stored;
  spdlog::warn("room {}: the face of avatar {} ({}) is not here; its viewers here go without it", room, info.id,
               info.asset);
  StoredAvatar missing;
  missing.asset = info.asset;
  return missing;
}

const StoredAvatar& procedural_face_for(const std::vector<StoredAvatar>& faces, const std::string& name) {
  return faces[std::hash<std::string>{}(name) % faces.size()];
}

void wear_face(Member& member, const StoredAvatar& face) {
  member.avatar = face;
  member.info.asset = face.asset;
  member.info.preview_bytes = static_cast<std::uint32_t>(face.preview ? face.preview->size() : 0);
  member.info.full_bytes = static_cast<std::uint32_t>(face.full ? face.full->size() : 0);
}

void log_face_replaced(const std::string& room, const std::string& name, const std::string& asset) {
  spdlog::info("room {}: {} wears a procedural face from now on: their avatar {} was deleted", room, name, asset);
}

void send_attention(Member& newcomer, const codec::Attention& attention) {
  const auto bytes = encode_shared(attention);
  newcomer.stream->charge(bytes->size());
  newcomer.stream->connection()->deliver(bytes);
}

}  // namespace fw::server
