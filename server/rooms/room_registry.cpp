#include "room_registry.hpp"

#include <cmath>

#include "peer_address.hpp"
#include "room.hpp"

namespace fw::server {

bool is_valid_room_name(std::string_view name) {
  if (name.empty() || name.size() > codec::kMaxRoomNameBytes) return false;
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
          c == '.'))
      return false;
  return true;
}

namespace {

/// `services` with another bus (its references cannot be reseated).
RoomServices with_bus(const RoomServices& services, RoomBus& bus) {
  return RoomServices{.config = services.config,
                      .metrics = services.metrics,
                      .physics_lod = services.physics_lod,
                      .abuse = services.abuse,
                      .workers = services.workers,
                      .store = services.store,
                      .procedural_faces = services.procedural_faces,
                      .bus = bus,
                      .draining = services.draining,
                      .speech = services.speech,
                      .face_stepper = services.face_stepper,
                      .face_models = services.face_models};
}

RoomShareLimits room_shares_of(const ServerConfig& config) {
  RoomShareLimits limits;
  limits.per_address = config.abuse.rooms_per_address;
  limits.per_block = config.abuse.rooms_per_block;
  limits.fresh_reserve = config.max_rooms * config.abuse.fresh_share_percent / 100;
  return limits;
}

/// What a person refused a new room by its shares reads, and what to do.
std::string share_refusal_text(RoomShareRefusal why, const RoomShareLimits& limits) {
  switch (why) {
    case RoomShareRefusal::address:
      return "your address has " + std::to_string(limits.per_address) +
             " rooms open already; join one that exists, or open one when one of yours closes";
    case RoomShareRefusal::block:
      return "your network has " + std::to_string(limits.per_block) +
             " rooms open already; join one that exists, or open one when one of them closes";
    default:
      return "the server's last free rooms are kept for networks that hold none; join one that exists, or try later";
  }
}

}  // namespace

RoomRegistry::RoomRegistry(const RoomServices& services, AddressLimits& addresses)
    : services_(services), preview_services_(with_bus(services, preview_bus_)), addresses_(addresses),
      preview_counts_(services.config.previews), shares_(room_shares_of(services.config)) {}
RoomRegistry::~RoomRegistry() = default;

std::shared_ptr<Room> RoomRegistry::find_or_create(const std::string& name, bool persistent, bool place) {
  std::shared_ptr<Room> room;
  {
    std::lock_guard lock(mutex_);
    if (auto it = rooms_.find(name); it != rooms_.end()) return it->second;
    if (closed_ || rooms_.size() >= services_.config.max_rooms) return nullptr;
    room = start_room(name, persistent);
  }
  if (place) services_.bus.room_opened(name);
  return room;
}

std::shared_ptr<Room> RoomRegistry::start_room(const std::string& name, bool persistent) {
  // In a cluster a room opens as a bridge; its owner (maybe this node) is
  // found or chosen by the bus.
  auto room =
      std::make_shared<Room>(services_, *this, name, persistent, next_seed_++, services_.bus.role_of_new_room());
  rooms_.emplace(name, room);
  room->start();
  return room;
}

std::shared_ptr<Room> RoomRegistry::find(const std::string& name) const {
  std::lock_guard lock(mutex_);
  const auto it = rooms_.find(name);
  return it == rooms_.end() ? nullptr : it->second;
}

std::vector<std::shared_ptr<Room>> RoomRegistry::all() const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<Room>> rooms;
  for (const auto& [name, room] : rooms_) rooms.push_back(room);
  for (const auto& [name, room] : previews_) rooms.push_back(room);
  return rooms;
}

RoomOpening RoomRegistry::open_preview(const std::string& address) {
  std::lock_guard lock(mutex_);
  if (closed_) return RoomOpening::refused(codec::CloseCode::shutting_down, "the server is shutting down; try again soon");
  if (auto refusal = preview_counts_.may_open(address))
    return RoomOpening::refused(refusal->code, std::move(refusal->why), Abuse::preview_limit);
  // '~' is not in a hello's room names: nobody can ask for this room.
  const std::string name = "~lab-" + std::to_string(next_preview_++);
  // Always owned here, on a bus of this node alone: nobody else joins it.
  auto room = std::make_shared<Room>(preview_services_, *this, name, false, next_seed_++, RoomRoleKind::owner, true);
  previews_.emplace(name, room);
  preview_counts_.opened(name, address);
  room->start();
  return RoomOpening::opened(room);
}

RoomOpening RoomRegistry::open_for(const std::string& name, const std::string& address) {
  std::unique_lock lock(mutex_);
  if (auto it = rooms_.find(name); it != rooms_.end()) return RoomOpening::opened(it->second);
  if (closed_) return RoomOpening::refused(codec::CloseCode::shutting_down, "the server is shutting down; try again soon");
  if (rooms_.size() >= services_.config.max_rooms)
    return RoomOpening::refused(codec::CloseCode::server_full, "the server holds its maximum number of rooms; try later");
  if (const auto wait = addresses_.take(AddressRate::room_creation, address)) {
    return RoomOpening::refused(codec::CloseCode::rate_limited,
                                "too many new rooms from your address; join one that exists, or try again in " +
                                    std::to_string(static_cast<long>(std::ceil(*wait))) + " s",
                                Abuse::room_creation);
  }
  const std::string block = address_group(address);
  if (const auto why = shares_.may_open(address, block, rooms_.size(), services_.config.max_rooms);
      why != RoomShareRefusal::none)
    return RoomOpening::refused(
        why == RoomShareRefusal::reserve ? codec::CloseCode::server_full : codec::CloseCode::rate_limited,
        share_refusal_text(why, shares_.limits()), Abuse::room_share);
  auto room = start_room(name, false);
  shares_.opened(name, address, block);
  lock.unlock();
  services_.bus.room_opened(name);
  return RoomOpening::opened(room);
}

void RoomRegistry::remove_if_empty(const std::shared_ptr<Room>& room) {
  std::lock_guard lock(mutex_);
  if (!room->unpeopled() || room->persistent()) return;
  if (const auto preview = previews_.find(room->name()); preview != previews_.end() && preview->second == room) {
    previews_.erase(preview);
    preview_counts_.closed(room->name());
    room->close();
    return;
  }
  auto it = rooms_.find(room->name());
  if (it == rooms_.end() || it->second != room) return;
  rooms_.erase(it);
  shares_.closed(room->name());
  room->close();
}

std::vector<RoomSummary> RoomRegistry::list() const {
  std::lock_guard lock(mutex_);
  std::vector<RoomSummary> out;
  for (const auto& [name, room] : rooms_) out.push_back({name, room->avatar_count(), room->person_count()});
  return out;
}

void RoomRegistry::close_all_rooms() {
  std::map<std::string, std::shared_ptr<Room>> rooms;
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
    rooms.swap(rooms_);
    for (const auto& [name, room] : rooms) shares_.closed(name);
    for (auto& [name, room] : previews_) {
      preview_counts_.closed(name);
      rooms.emplace(name, std::move(room));
    }
    previews_.clear();
  }
  for (auto& [name, room] : rooms) room->close();
}

}  // namespace fw::server
