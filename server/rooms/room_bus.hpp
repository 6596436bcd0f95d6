#pragma once
// How a room reaches the other nodes of a cluster (cluster_node.hpp), seen
// from the room. Every room has one, given when it is made: in one process
// it is LocalRoomBus (local_room_bus.hpp), where every room is this node's
// and there is nobody to tell; so room code never asks whether there is a
// cluster, it tells the bus and the bus knows. Calls return at once (the
// cluster's bus queues them for Redis) and may come from any room's strand.
#include <cstdint>
#include <string>

#include "bridge_message.hpp"

namespace fw::server {

/// What a room does on this node: simulates it (the owner), or relays the
/// owner on another node to its people here (a bridge).
enum class RoomRoleKind { owner, bridge };

class RoomBus {
 public:
  virtual ~RoomBus() = default;
  /// What a room opened here for a joiner starts as: in a cluster a bridge,
  /// whose owner the bus finds or places (room_opened); alone, the owner.
  virtual RoomRoleKind role_of_new_room() const = 0;
  /// A room was opened here for a joiner (in the bridge role): the bus
  /// finds or places its owner (perhaps this node, then it takes it over).
  virtual void room_opened(const std::string& room) = 0;
  /// This node's name in the cluster.
  virtual const std::string& node() const = 0;
  /// The owner's news for every node that bridges clients into `room`.
  virtual void send_down(const std::string& room, bridge::Bytes message) = 0;
  /// A bridging node's request for the owner of `room`.
  virtual void send_up(const std::string& room, bridge::Bytes message) = 0;
  /// The owner's record of its room, for whoever takes it over: a member
  /// (kept or forgotten), the behavior state, a chat line of the tail.
  virtual void keep_member(const std::string& room, const bridge::MemberRecord& member) = 0;
  virtual void forget_member(const std::string& room, std::uint32_t avatar) = 0;
  virtual void keep_state(const std::string& room, bridge::Bytes state) = 0;
  virtual void keep_chat(const std::string& room, bridge::Bytes chat_message) = 0;
  /// The owner closed `room` for want of people: its record goes.
  virtual void room_closed(const std::string& room) = 0;
};

}  // namespace fw::server
