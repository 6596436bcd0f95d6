#pragma once
// What a room does with what it is asked, in the role it plays on this
// node: OwnedRoom simulates the room (owned_room.hpp), BridgedRoom relays
// its owner on another node of a cluster to the people here
// (bridged_room.hpp). Room (room.hpp) holds one role at a time, hands it
// every request on the room's strand, and puts another role in its place
// when the room changes hands; sessions and the registry only ever see
// Room. A kind of room to come (a private preview simulating one person's
// face for them alone) is one more role.
//
// Every call runs on the room's strand, while the room is open.
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "bridge_message.hpp"
#include "fw/codec/messages.hpp"
#include "join_request.hpp"
#include "room_bus.hpp"
#include "room_members.hpp"
#include "room_services.hpp"
#include "room_simulation.hpp"

namespace fw::server {

/// What a role leaves to its successor: the people connected here, with
/// their streams, and the joins it had not answered yet.
struct RoomHandover {
  std::map<std::uint32_t, Member> members;
  std::vector<JoinRequest> waiting_joins;
};

class RoomRole {
 public:
  virtual ~RoomRole() = default;
  virtual RoomRoleKind kind() const = 0;

  /// Seats the joiner (welcome, stream header, presence to the others, then
  /// connection->joined), or closes its connection (refused).
  virtual void join(JoinRequest request) = 0;
  virtual void leave(std::uint32_t avatar) = 0;
  virtual void chat(std::uint32_t avatar, std::string text) = 0;
  virtual void command(std::uint32_t avatar, const codec::Command& command) = 0;
  /// The client lost track of `avatars` (empty: all).
  virtual void resync(std::uint32_t avatar, const std::vector<std::uint32_t>& avatars) = 0;
  /// A person's new budget (0: the server's default).
  virtual void set_rate(std::uint32_t avatar, std::uint32_t bps) = 0;
  virtual void replace_deleted_avatar(const std::string& asset) = 0;
  /// One tick of the room's timer, due at `due`.
  virtual void tick(std::chrono::steady_clock::time_point due) = 0;
  /// A tick in two halves around its faces' step, for the role that
  /// simulates the room: begin_tick hands out the faces whose tissue needs
  /// stepping (Room steps them with the other rooms', face_stepper.hpp),
  /// finish_tick runs on the strand once they are stepped. A role that
  /// simulates nothing ticks at once and hands out none.
  virtual RoomSimulation::TickFaces begin_tick(std::chrono::steady_clock::time_point due) {
    tick(due);
    return {};
  }
  virtual void finish_tick() {}
  /// Nobody keeps the room open here.
  virtual bool unpeopled() const = 0;
  /// Joins wait for an answer from elsewhere: the room stays open for them.
  virtual bool awaiting_joins() const { return false; }
  /// The room closes: every connection here is closed, every member let go.
  virtual void close() = 0;
  /// Another role takes the room over: what it inherits (and this role
  /// forgets).
  virtual RoomHandover hand_over() = 0;

  // A cluster's news (room_bus.hpp); a role it is not for ignores it.
  /// A bridging node's request, for the owner.
  virtual void on_up(bridge::Up&) {}
  /// The owner's news, for a bridge.
  virtual void on_down(bridge::Down&) {}
  /// The people bridged from `node` are away (it stopped answering), or back.
  virtual void node_gone(const std::string&) {}
  virtual void node_back(const std::string&) {}
  /// Writes the room's whole record again (Redis came back).
  virtual void keep_all() {}
  /// Asks the owner for its roster again (Redis came back).
  virtual void ask_roster() {}
  /// Another node owns the room now: the people here are asked to come back.
  virtual void step_down() {}
  /// `avatar`'s own face, built on the worker pool from the package of
  /// version `version` (face_models.hpp): worn if it still wears that one.
  virtual void wear_face(std::uint32_t, const std::string&, std::shared_ptr<const FaceModel>) {}
};

}  // namespace fw::server
