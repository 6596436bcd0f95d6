#include "demo_room.hpp"

#include "demo_faces.hpp"
#include "room.hpp"
#include "room_registry.hpp"

namespace fw::server {

std::optional<std::vector<StoredAvatar>> make_demo_avatars(const ServerConfig& config, AvatarStore& store,
                                                           std::string& error) {
  const std::uint32_t needed = config.demo_room ? kLobbyAvatars : 1;
  if (config.demo_faces < needed) {
    error = "demo_faces must be at least " + std::to_string(needed) +
            " (the lobby seats 3 faces; a client without a package takes 1)";
    return std::nullopt;
  }
  std::vector<StoredAvatar> faces;
  for (std::uint32_t i = 0; i < config.demo_faces; ++i) {
    const auto package = make_demo_package(i);
    auto stored = store.put_own_face(package, error);  // made again at every start: found again
    if (!stored) {
      error = "the demo face " + std::to_string(i) + " is not a valid package: " + error;
      return std::nullopt;
    }
    faces.push_back(std::move(*stored));
  }
  return faces;
}

void open_demo_room(RoomRegistry& rooms, const std::vector<StoredAvatar>& faces, std::function<void()> seated) {
  auto lobby = rooms.find_or_create("lobby", /*persistent=*/true);
  // Opened as a bridge (a cluster), the lobby gets its residents from its owner.
  if (lobby->role() == RoomRoleKind::bridge) return seated();
  seat_lobby_residents(faces, lobby);
  lobby->then(std::move(seated));
}

void seat_lobby_residents(const std::vector<StoredAvatar>& faces, const std::shared_ptr<Room>& lobby) {
  const char* names[kLobbyAvatars] = {"Ada", "Bruno", "Chidi"};  // Ada joins first: she leads
  for (std::uint32_t i = 0; i < kLobbyAvatars; ++i) {
    JoinRequest request;
    request.name = names[i];
    request.avatar = faces[i];
    lobby->join(std::move(request));
  }
}

}  // namespace fw::server
