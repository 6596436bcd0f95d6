#pragma once
// All rooms by name: created on first join (up to the room limit), removed
// when their last person leaves (except persistent ones, like the lobby).
// Each room is made with the services it uses (RoomServices) and starts in
// the role the bus gives a new room. The sessions open on the server are
// SessionRegistry's (session_registry.hpp).
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "fw/codec/messages.hpp"
#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "local_room_bus.hpp"
#include "preview_limits.hpp"
#include "room_services.hpp"
#include "room_shares.hpp"

namespace fw::server {

class Room;

/// A room for a hello, or why there is none.
struct RoomOpening {
  std::shared_ptr<Room> room;
  codec::CloseCode code = codec::CloseCode::normal;
  std::string refusal;
  std::optional<Abuse> abuse;  ///< how the refusal is counted, if it is abuse

  static RoomOpening opened(std::shared_ptr<Room> room) {
    RoomOpening opening;
    opening.room = std::move(room);
    return opening;
  }
  static RoomOpening refused(codec::CloseCode code, std::string why, std::optional<Abuse> abuse = std::nullopt) {
    RoomOpening opening;
    opening.code = code;
    opening.refusal = std::move(why);
    opening.abuse = abuse;
    return opening;
  }
};

struct RoomSummary {
  std::string name;
  std::size_t avatars = 0;
  std::size_t persons = 0;
};

class RoomRegistry {
 public:
  /// `addresses`: how many rooms each address may still open.
  RoomRegistry(const RoomServices& services, AddressLimits& addresses);
  ~RoomRegistry();

  /// The room called `name`, created (and started) if needed; null when the
  /// server already holds its maximum number of rooms, or has stopped. In a
  /// cluster a new room is a bridge (RoomBus::role_of_new_room), and the
  /// bus is told to `place` it (unless the bus itself asks, taking the room
  /// over).
  std::shared_ptr<Room> find_or_create(const std::string& name, bool persistent = false, bool place = true);
  /// The room called `name` for a person from `address` (address_key()):
  /// created if needed, when that address may still create rooms
  /// (AbuseLimits::room_creations), it and its block hold fewer than their
  /// shares of open rooms (RoomShares), and the server holds fewer than its
  /// maximum (its last rooms only for a block that holds none).
  RoomOpening open_for(const std::string& name, const std::string& address);
  /// A face-lab preview for a person from `address` (PROTOCOL.md 5.16): a
  /// private room of one, owned here, under a name no hello can give (so
  /// nobody else joins it) and never listed; refused past the server's or
  /// the address's share of previews (PreviewLimits).
  RoomOpening open_preview(const std::string& address);
  /// The room called `name` if this node holds it (owned or bridged); never a preview.
  std::shared_ptr<Room> find(const std::string& name) const;
  /// Every room this node holds, previews too.
  std::vector<std::shared_ptr<Room>> all() const;
  /// Closes and forgets `room` if nobody is in it any more.
  void remove_if_empty(const std::shared_ptr<Room>& room);
  std::vector<RoomSummary> list() const;

  /// Stops every room; no room opens after this.
  void close_all_rooms();

 private:
  /// Makes and starts a room; the caller holds mutex_.
  std::shared_ptr<Room> start_room(const std::string& name, bool persistent);

  RoomServices services_;
  /// Previews are this node's alone: their rooms speak to no other node and
  /// keep nothing in Redis, where every node's "~lab-1" would meet.
  LocalRoomBus preview_bus_;
  RoomServices preview_services_;
  AddressLimits& addresses_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<Room>> rooms_;
  /// Face-lab previews, apart from the rooms: not found by name, not listed.
  std::map<std::string, std::shared_ptr<Room>> previews_;
  PreviewCounts preview_counts_;
  std::uint64_t next_preview_ = 1;
  /// Who opened the rooms open_for() opened.
  RoomShares shares_;
  std::uint64_t next_seed_ = 1;
  bool closed_ = false;  ///< close_all_rooms() ran: the worker pool is to run out of work
};

/// Whether `name` is 1 .. 64 characters of A-Z a-z 0-9 _ - . (PROTOCOL.md, hello).
bool is_valid_room_name(std::string_view name);

}  // namespace fw::server
