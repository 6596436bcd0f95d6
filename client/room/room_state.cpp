#include "room_state.hpp"

#include <algorithm>
#include <cstdio>

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

RoomScene RoomState::scene(std::chrono::steady_clock::time_point now, const std::string& your_name) const {
  RoomScene scene;
  scene.now = now;
  scene.you = you;
  scene.your_name = your_name;
  std::map<std::uint32_t, codec::FaceParams> decoded;
  for (AvatarFace& face : faces(now)) decoded[face.avatar] = face.params;
  for (const auto& [id, avatar] : avatars) {
    SceneMember member{id, avatar.info.name, avatar.info.seat, std::nullopt, {id, codec::AttentionTarget::room, 0}};
    if (const auto it = decoded.find(id); it != decoded.end()) member.face = it->second;
    // Muted: drawn at rest whatever the stream says, once it has a face at all.
    if (mutes.mutes(id, avatar.info.name, you)) {
      member.still = true;
      member.name += " (muted)";
      if (member.face) member.face = MuteList::still_face();
    }
    if (const auto it = attention.find(id); it != attention.end()) member.attention = it->second;
    if (id == scene.you && !avatar.info.name.empty()) scene.your_name = avatar.info.name;
    scene.members.push_back(std::move(member));
  }
  for (auto it = events.rbegin(); it != events.rend(); ++it)
    if (it->kind == "chat") {
      scene.caption = it->name + ": " + it->text;
      break;
    }
  return scene;
}

void RoomState::connection_started() {
  joined = false;
  decoder = codec::RoomDecoder();
}

void RoomState::welcomed(const codec::Welcome& welcome, const PackageBytes& own_package, Clock::time_point now) {
  stats.joined(now);
  joined = true;
  you = welcome.you;
  room = welcome.room;
  tick_hz = std::max<int>(1, welcome.tick_hz);
  std::map<std::uint32_t, RoomAvatar> present;
  for (const codec::AvatarInfo& info : welcome.avatars) {
    RoomAvatar& avatar = present[info.id];
    const auto old = avatars.find(info.id);
    if (old != avatars.end() && old->second.info.asset == info.asset && !info.asset.empty()) avatar = old->second;
    avatar.info = info;
  }
  avatars = std::move(present);
  attention.clear();  // the server sends everyone's after the welcome
  const auto own = avatars.find(welcome.you);
  if (own_package && own != avatars.end() && !own->second.package) {
    own->second.package = own_package;
    own->second.package_quality = codec::PackageChunk::Quality::full;
    ++own->second.package_serial;
    stats.package(welcome.you, true, now);
  }
}

void RoomState::avatar_joined(const codec::AvatarInfo& info) {
  avatars[info.id].info = info;
  record({"joined", info.name, ""});
}

std::string RoomState::avatar_left(std::uint32_t avatar) {
  std::string name = name_of(avatar);
  avatars.erase(avatar);
  attention.erase(avatar);
  unit_morphs.erase(avatar);
  decoder.remove(avatar);
  record({"left", name, ""});
  return name;
}

bool RoomState::unit_morphs_arrived(const codec::UnitMorphs& morphs) {
  const auto held = unit_morphs.find(morphs.avatar);
  if (held != unit_morphs.end() && held->second.version >= morphs.version) return false;  // not newer
  unit_morphs[morphs.avatar] = morphs;
  return true;
}

void RoomState::seats_changed(const codec::Seats& seats) {
  for (const codec::Seats::Entry& entry : seats.seats)
    if (auto it = avatars.find(entry.avatar); it != avatars.end()) it->second.info.seat = entry.seat;
}

void RoomState::attention_changed(const codec::Attention& message) {
  // An entry for an avatar that already left (the messages crossed) is dropped.
  for (const codec::Attention::Entry& entry : message.entries)
    if (avatars.count(entry.avatar)) attention[entry.avatar] = entry;
}

std::string RoomState::chat_line(const codec::Chat& chat) {
  std::string name = name_of(chat.from);
  if (muted(chat.from))
    mutes.line_hidden(name);
  else
    record({"chat", name, chat.text});
  return name;
}

std::optional<std::string> RoomState::line_begun(const codec::Speaking& speaking, Clock::time_point now) {
  if (muted(speaking.avatar)) return std::nullopt;  // its chat line is hidden (and counted) already
  RoomEventRecord record_of{"speaking", name_of(speaking.avatar), speaking.text};
  record_of.language = speaking.language;
  record_of.duration_ms = speaking.duration_ms;
  record_of.tick = speaking.tick;
  std::string line = record_of.name + " says (" + speaking.language + ", " + std::to_string(speaking.duration_ms) +
                     " ms): " + speaking.text;
  record(std::move(record_of));
  if (const auto joined_at = stats.joined_at()) {
    char at[32];
    std::snprintf(at, sizeof at, "[%.1f s] ", std::chrono::duration<double>(now - *joined_at).count());
    line = at + line;
  }
  return line;
}

bool RoomState::package_arrived(AssembledPackage package, Clock::time_point now) {
  using Quality = codec::PackageChunk::Quality;
  const auto it = avatars.find(package.avatar);
  if (it == avatars.end()) return false;
  RoomAvatar& avatar = it->second;
  if (avatar.package_quality == Quality::full && package.quality == Quality::preview) return false;
  stats.package(package.avatar, package.quality == Quality::full, now);
  avatar.package = std::make_shared<const std::vector<std::uint8_t>>(std::move(package.bytes));
  avatar.package_quality = package.quality;
  ++avatar.package_serial;
  return true;
}

bool RoomState::decode_room_frame(std::span<const std::uint8_t> room_frame, Clock::time_point now) {
  const codec::RoomDecoder::Result result = decoder.decode(room_frame);
  if (result.error != codec::DecodeError::ok) {
    stats.decode_error();
    return false;
  }
  bool any = false;
  for (const auto& [id, error] : result.avatars) {
    if (error != codec::DecodeError::ok) {
      stats.decode_error();
      continue;
    }
    any = true;
    stats.frame(id, name_of(id));
    const auto it = avatars.find(id);
    if (it != avatars.end()) it->second.last_frame_at = now;
  }
  return any;
}

}  // namespace fw::client
