#pragma once
// What every role of a room keeps of each avatar seated in it, and what it
// tells and sends the people connected here about the others: their
// presence, their faces, their welcome. OwnedRoom and BridgedRoom keep
// more per member (OwnedMember); these helpers take either's members.
// Called on the room's strand.
#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "avatar_store.hpp"
#include "fw/codec/messages.hpp"
#include "join_request.hpp"
#include "metrics.hpp"
#include "subscriber_stream.hpp"

namespace fw::server {

struct Member {
  codec::AvatarInfo info;
  StoredAvatar avatar;
  std::unique_ptr<SubscriberStream> stream;  ///< a person connected here; null otherwise
};

/// The face of a member seated elsewhere (by another node, or before a
/// takeover), from the store here: a demo face, an upload, or the
/// cluster's copy. Missing, its viewers here go without it.
StoredAvatar stored_face_of(AvatarStore& store, const codec::AvatarInfo& info, const std::string& room);

/// The procedural face of a person called `name`, one of `faces` (the demo
/// faces), chosen by the name so that it stays the same; also the face
/// shown in place of an avatar its uploader deleted. `faces` is not empty.
const StoredAvatar& procedural_face_for(const std::vector<StoredAvatar>& faces, const std::string& name);

/// `wanted`, unless it is one of the procedural `faces` and someone among
/// `members` already wears it: then the first of `faces` that nobody there
/// wears (still `wanted` when all are worn). Two people without a photo
/// who look alike cannot tell each other apart, nor a resident from them.
template <class Members>
const StoredAvatar& unworn_procedural_face(const Members& members, const std::vector<StoredAvatar>& faces,
                                           const StoredAvatar& wanted) {
  const auto worn = [&](const std::string& asset) {
    for (const auto& [id, member] : members)
      if (member.info.asset == asset) return true;
    return false;
  };
  const bool procedural =
      std::any_of(faces.begin(), faces.end(), [&](const StoredAvatar& f) { return f.asset == wanted.asset; });
  if (!procedural || !worn(wanted.asset)) return wanted;
  for (const StoredAvatar& face : faces)
    if (!worn(face.asset)) return face;
  return wanted;
}

/// `member` wears `face` from now on (its own was deleted by its uploader).
void wear_face(Member& member, const StoredAvatar& face);

/// The welcome to a person who joins and the stream that follows it;
/// `others` are the members listed before the newcomer.
template <class Members>
std::unique_ptr<SubscriberStream> welcome(const Members& others, const Member& newcomer, const JoinRequest& request,
                                          const std::string& room, int tick_hz, Metrics& metrics) {
  codec::Welcome welcome;
  welcome.protocol_version = request.stream.protocol_version;  // a version-3 client reads a version-3 welcome
  welcome.you = newcomer.info.id;
  welcome.resume = request.resume;
  welcome.room = room;
  welcome.tick_hz = static_cast<std::uint8_t>(tick_hz);
  welcome.max_bps = request.stream.budget_bps;
  // (A person taking a seat back is a member already: listed once, last.)
  for (const auto& [other_id, other] : others)
    if (other_id != newcomer.info.id && welcome.avatars.size() + 1 < codec::kMaxWelcomeAvatars)
      welcome.avatars.push_back(other.info);
  welcome.avatars.push_back(newcomer.info);
  const auto welcome_bytes = encode_shared(welcome);
  request.connection->joined(newcomer.info.id, welcome_bytes);
  // The stream's header follows the welcome; then everyone's face.
  auto stream = std::make_unique<SubscriberStream>(request.stream, request.connection, metrics);
  stream->charge(welcome_bytes->size());
  for (const auto& [other_id, other] : others)
    if (other_id != newcomer.info.id) stream->add_avatar(other_id, other.avatar.preview, other.avatar.full);
  // A client that uploaded its package holds it: its own face costs its link nothing.
  if (request.stream.own_package) stream->add_avatar(newcomer.info.id, nullptr, nullptr);
  else stream->add_avatar(newcomer.info.id, newcomer.avatar.preview, newcomer.avatar.full);
  return stream;
}

/// Presence to everyone connected here, and the newcomer's face in their streams.
template <class Members>
void introduce_to_others(Members& members, const Member& newcomer) {
  const auto joined = encode_shared(codec::Presence{codec::Presence::Change::joined, newcomer.info});
  for (auto& [other_id, other] : members) {
    if (!other.stream) continue;
    other.stream->post_presence(codec::Presence::Change::joined, newcomer.info.id, joined);
    other.stream->add_avatar(newcomer.info.id, newcomer.avatar.preview, newcomer.avatar.full);
  }
}

/// `avatar` left: its face goes from everyone's stream here, and they are told.
template <class Members>
void tell_left(Members& members, std::uint32_t avatar, bool person) {
  codec::AvatarInfo info;
  info.id = avatar;
  info.person = person;
  const auto left = encode_shared(codec::Presence{codec::Presence::Change::left, info});
  for (auto& [id, member] : members) {
    if (!member.stream) continue;
    member.stream->remove_avatar(avatar);
    member.stream->post_presence(codec::Presence::Change::left, avatar, left);
  }
}

/// `avatar`, already erased from `members`, left: what was last said of
/// whom it attends goes, the room's counts (RoomCounts) and the server's
/// avatar metric drop, and the people connected here are told. Both roles
/// end a departure this way.
template <class Members, class Counts>
void count_departure(Members& members, std::map<std::uint32_t, codec::Attention::Entry>& attention_sent,
                     Counts& counts, Metrics& metrics, std::uint32_t avatar, bool person) {
  attention_sent.erase(avatar);
  counts.avatars.fetch_sub(1);
  metrics.avatars.fetch_sub(1);
  if (person) counts.persons.fetch_sub(1);
  tell_left(members, avatar, person);
}

/// The room closes: every member's connection is closed and the members
/// forgotten.
template <class Members>
void close_every_member(Members& members) {
  for (auto& [id, member] : members)
    if (member.stream) member.stream->connection()->close(codec::CloseCode::shutting_down, "the room closed");
  members.clear();
}

/// The log line of a face replaced (replace_deleted_face).
void log_face_replaced(const std::string& room, const std::string& name, const std::string& asset);

/// Whoever wears `asset` here (deleted by its uploader) wears the
/// procedural face of their name from now on, and everyone here who sees
/// them is sent its package; `replaced(member)` runs for each. Their seat
/// and mood do not change, only the face the others see, and nothing new
/// goes on the wire: clients put a full package they are sent again in
/// place of the one they hold (PROTOCOL.md 5.7).
template <class Members, class Replaced>
void replace_deleted_face(Members& members, const std::string& asset, const std::vector<StoredAvatar>& faces,
                          const std::string& room, Replaced replaced) {
  for (auto& [id, member] : members) {
    if (member.info.asset != asset) continue;
    const StoredAvatar& face = procedural_face_for(faces, member.info.name);
    wear_face(member, face);
    for (auto& [viewer_id, viewer] : members)
      if (viewer.stream) viewer.stream->replace_package(id, face.preview, face.full);
    replaced(member);
    log_face_replaced(room, member.info.name, asset);
  }
}

/// The client of `avatar` lost track of `avatars` (empty: all): key frames follow.
template <class Members>
void resync_member(Members& members, std::uint32_t avatar, const std::vector<std::uint32_t>& avatars) {
  auto it = members.find(avatar);
  if (it != members.end() && it->second.stream) it->second.stream->force_key_frames(avatars);
}

/// The budget the client of `avatar` asked for (0: the server's default),
/// within the server's most.
template <class Members>
void set_member_budget(Members& members, std::uint32_t avatar, std::uint32_t bps, std::uint32_t default_bps,
                       std::uint32_t max_bps) {
  auto it = members.find(avatar);
  if (it == members.end() || !it->second.stream) return;
  it->second.stream->set_budget(std::min(bps == 0 ? default_bps : bps, max_bps));
}

/// The attention message, charged to the newcomer's stream and sent after its welcome.
void send_attention(Member& newcomer, const codec::Attention& attention);

}  // namespace fw::server
