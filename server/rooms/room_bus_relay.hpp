#pragma once
// The one RoomBus every room of a server holds, from the server's start to
// its end. It is a LocalRoomBus until a cluster node attaches itself
// (ClusterNode::start, before the server takes its first connection), and
// forwards every call to that node from then on until it detaches (once the
// rooms stopped).
//
// Why a relay: the rooms' services are made with the server core, before
// the cluster node can be (it needs the I/O loop and the server's
// listeners); a room holds a bus that never changes, and never asks
// whether there is a cluster. Thread-safe: any room's strand may call while
// the node attaches.
#include <atomic>

#include "local_room_bus.hpp"

namespace fw::server {

class RoomBusRelay : public RoomBus {
 public:
  /// Every call goes to `cluster` from now on; it outlives its attachment.
  void attach(RoomBus& cluster) { target_.store(&cluster); }
  /// Back to the local bus (the cluster node stops).
  void detach() { target_.store(&local_); }

  RoomRoleKind role_of_new_room() const override { return target().role_of_new_room(); }
  void room_opened(const std::string& room) override { target().room_opened(room); }
  const std::string& node() const override { return target().node(); }
  void send_down(const std::string& room, bridge::Bytes message) override {
    target().send_down(room, std::move(message));
  }
  void send_up(const std::string& room, bridge::Bytes message) override { target().send_up(room, std::move(message)); }
  void keep_member(const std::string& room, const bridge::MemberRecord& member) override {
    target().keep_member(room, member);
  }
  void forget_member(const std::string& room, std::uint32_t avatar) override { target().forget_member(room, avatar); }
  void keep_state(const std::string& room, bridge::Bytes state) override {
    target().keep_state(room, std::move(state));
  }
  void keep_chat(const std::string& room, bridge::Bytes chat_message) override {
    target().keep_chat(room, std::move(chat_message));
  }
  void room_closed(const std::string& room) override { target().room_closed(room); }

 private:
  RoomBus& target() const { return *target_.load(); }

  LocalRoomBus local_;
  std::atomic<RoomBus*> target_{&local_};
};

}  // namespace fw::server
