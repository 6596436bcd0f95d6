#pragma once
// The RoomBus of a server alone (no --redis): every room is owned here,
// there is no other node to tell anything, and no record to keep for a
// successor. Stateless, so thread-safe.
#include "room_bus.hpp"

namespace fw::server {

class LocalRoomBus : public RoomBus {
 public:
  RoomRoleKind role_of_new_room() const override { return RoomRoleKind::owner; }
  void room_opened(const std::string&) override {}
  /// A server alone has no name among others: records it would write name no node.
  const std::string& node() const override { return node_; }
  void send_down(const std::string&, bridge::Bytes) override {}
  void send_up(const std::string&, bridge::Bytes) override {}
  void keep_member(const std::string&, const bridge::MemberRecord&) override {}
  void forget_member(const std::string&, std::uint32_t) override {}
  void keep_state(const std::string&, bridge::Bytes) override {}
  void keep_chat(const std::string&, bridge::Bytes) override {}
  void room_closed(const std::string&) override {}

 private:
  const std::string node_;
};

}  // namespace fw::server
