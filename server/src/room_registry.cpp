#include "room_registry.hpp"

#include <cmath>

#include "client_session.hpp"
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

RoomRegistry::RoomRegistry(ServerContext& context) : context_(context) {}
RoomRegistry::~RoomRegistry() = default;

std::shared_ptr<Room> RoomRegistry::find_or_create(const std::string& name, bool persistent) {
  std::lock_guard lock(mutex_);
  if (auto it = rooms_.find(name); it != rooms_.end()) return it->second;
  if (closed_ || rooms_.size() >= context_.config.max_rooms) return nullptr;
  auto room = std::make_shared<Room>(context_, name, persistent, next_seed_++);
  rooms_.emplace(name, room);
  room->start();
  return room;
}

RoomOpening RoomRegistry::open_for(const std::string& name, const std::string& address) {
  std::lock_guard lock(mutex_);
  if (auto it = rooms_.find(name); it != rooms_.end()) return RoomOpening::opened(it->second);
  if (closed_) return RoomOpening::refused(codec::CloseCode::shutting_down, "the server is shutting down; try again soon");
  if (rooms_.size() >= context_.config.max_rooms)
    return RoomOpening::refused(codec::CloseCode::server_full, "the server holds its maximum number of rooms; try later");
  if (const auto wait = context_.addresses->take(AddressRate::room_creation, address)) {
    return RoomOpening::refused(codec::CloseCode::rate_limited,
                                "too many new rooms from your address; join one that exists, or try again in " +
                                    std::to_string(static_cast<long>(std::ceil(*wait))) + " s",
                                Abuse::room_creation);
  }
  auto room = std::make_shared<Room>(context_, name, false, next_seed_++);
  rooms_.emplace(name, room);
  room->start();
  return RoomOpening::opened(room);
}

void RoomRegistry::remove_if_empty(const std::shared_ptr<Room>& room) {
  std::lock_guard lock(mutex_);
  if (room->person_count() != 0 || room->persistent()) return;
  auto it = rooms_.find(room->name());
  if (it == rooms_.end() || it->second != room) return;
  rooms_.erase(it);
  room->close();
}

std::vector<RoomSummary> RoomRegistry::list() const {
  std::lock_guard lock(mutex_);
  std::vector<RoomSummary> out;
  for (const auto& [name, room] : rooms_) out.push_back({name, room->avatar_count(), room->person_count()});
  return out;
}

void RoomRegistry::add_session(const std::shared_ptr<ClientSession>& session) {
  std::lock_guard lock(mutex_);
  sessions_.emplace(session.get(), session);
}

void RoomRegistry::remove_session(const ClientSession* session) {
  std::lock_guard lock(mutex_);
  sessions_.erase(session);
}

std::size_t RoomRegistry::session_count() const {
  std::lock_guard lock(mutex_);
  return sessions_.size();
}

void RoomRegistry::close_all_sessions() {
  std::vector<std::shared_ptr<ClientSession>> open;
  {
    std::lock_guard lock(mutex_);
    for (auto& [key, weak] : sessions_)
      if (auto session = weak.lock()) open.push_back(std::move(session));
  }
  for (auto& session : open)
    session->close(codec::CloseCode::shutting_down, "the server is shutting down; reconnect in a moment");
}

void RoomRegistry::close_all_rooms() {
  std::map<std::string, std::shared_ptr<Room>> rooms;
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
    rooms.swap(rooms_);
  }
  for (auto& [name, room] : rooms) room->close();
}

}  // namespace fw::server
