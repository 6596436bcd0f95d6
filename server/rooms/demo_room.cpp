#include "demo_room.hpp"

#include "demo_faces.hpp"
#include "room.hpp"
#include "room_members.hpp"
#include "room_registry.hpp"

namespace fw::server {

bool make_demo_avatars(ServerContext& context, std::string& error) {
  const std::uint32_t needed = context.config.demo_room ? kLobbyAvatars : 1;
  if (context.config.demo_faces < needed) {
    error = "demo_faces must be at least " + std::to_string(needed) +
            " (the lobby seats 3 faces; a client without a package takes 1)";
    return false;
  }
  for (std::uint32_t i = 0; i < context.config.demo_faces; ++i) {
    const auto package = make_demo_package(i);
    auto stored = context.store->put_own_face(package, error);  // made again at every start: found again
    if (!stored) {
      error = "the demo face " + std::to_string(i) + " is not a valid package: " + error;
      return false;
    }
    context.demo_avatars.push_back(std::move(*stored));
  }
  return true;
}

const StoredAvatar& procedural_face_for(const ServerContext& context, const std::string& name) {
  return procedural_face_for(context.demo_avatars, name);
}

void open_demo_room(ServerContext& context, std::function<void()> seated) {
  auto lobby = context.rooms->find_or_create("lobby", /*persistent=*/true);
  // Opened as a bridge (a cluster), the lobby gets its residents from its owner.
  if (lobby->role() == RoomRoleKind::bridge) return seated();
  seat_lobby_residents(context, lobby);
  lobby->then(std::move(seated));
}

void seat_lobby_residents(ServerContext& context, const std::shared_ptr<Room>& lobby) {
  const char* names[kLobbyAvatars] = {"Ada", "Bruno", "Chidi"};  // Ada joins first: she leads
  for (std::uint32_t i = 0; i < kLobbyAvatars; ++i) {
    JoinRequest request;
    request.name = names[i];
    request.avatar = context.demo_avatars[i];
    lobby->join(std::move(request));
  }
}

}  // namespace fw::server
