#pragma once
// Where a cluster keeps things in Redis, and the channels its nodes talk on
// (server/CLUSTER.md lists them). One place, so that every node names them
// alike.
#include <string>

namespace fw::server::cluster_keys {

inline const std::string kPrefix = "fw:";
/// The set of node names that ever reported; a node whose `node_alive`
/// key expired is dead.
inline const std::string kNodes = kPrefix + "nodes";
/// The set of rooms that have an owner's record.
inline const std::string kRooms = kPrefix + "rooms";
/// The key every node signs avatar keys with (the first node's).
inline const std::string kServerKey = kPrefix + "server-key";
/// The set of avatar ids kept in Redis.
inline const std::string kAvatars = kPrefix + "avatars";
/// The set of avatar ids their uploaders deleted: a node that was away
/// when it was told drops its copy when it comes back, instead of sharing
/// it again.
inline const std::string kDeletedAvatars = kPrefix + "avatars:deleted";
/// Channel: an avatar id its uploader deleted on one node; the others drop theirs.
inline const std::string kAvatarDeletions = kPrefix + "avatar-deletions";
/// Channel: what each node spent of the per-address limits.
inline const std::string kLimitsChannel = kPrefix + "limits";

inline std::string node_alive(const std::string& node) { return kPrefix + "node:" + node; }
inline std::string node_inbox(const std::string& node) { return kPrefix + "node:" + node + ":inbox"; }
inline std::string room_owner(const std::string& room) { return kPrefix + "room:" + room + ":owner"; }
inline std::string room_members(const std::string& room) { return kPrefix + "room:" + room + ":members"; }
inline std::string room_state(const std::string& room) { return kPrefix + "room:" + room + ":state"; }
inline std::string room_chat(const std::string& room) { return kPrefix + "room:" + room + ":chat"; }
inline std::string room_down(const std::string& room) { return kPrefix + "room:" + room + ":down"; }
inline std::string room_up(const std::string& room) { return kPrefix + "room:" + room + ":up"; }
inline std::string avatar(const std::string& asset) { return kPrefix + "avatar:" + asset; }
/// A hash of an avatar's saved looks: name -> script; expires with the avatar's copy.
inline std::string avatar_looks(const std::string& asset) { return kPrefix + "avatar:" + asset + ":looks"; }

/// The room a room channel names ("fw:room:NAME:down" -> NAME), and which
/// way it goes; empty when `channel` is no room channel.
struct RoomChannel {
  std::string room;
  bool down = false;
};
inline RoomChannel parse_room_channel(const std::string& channel) {
  const std::string head = kPrefix + "room:";
  if (channel.rfind(head, 0) != 0) return {};
  for (const bool down : {true, false}) {
    const std::string tail = down ? ":down" : ":up";
    if (channel.size() > head.size() + tail.size() && channel.ends_with(tail))
      return {channel.substr(head.size(), channel.size() - head.size() - tail.size()), down};
  }
  return {};
}

}  // namespace fw::server::cluster_keys
