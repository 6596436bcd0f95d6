#include "demo_room.hpp"

#include "demo_faces.hpp"
#include "resident_faces.hpp"
#include "room.hpp"
#include "room_registry.hpp"

namespace fw::server {

std::optional<std::vector<StoredAvatar>> make_demo_avatars(const ServerConfig& config, AvatarStore& store,
                                                           std::string& error) {
  if (config.demo_faces < 1) {
    error = "demo_faces must be at least 1 (a client without a package takes one)";
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

std::optional<std::vector<StoredAvatar>> store_resident_faces(AvatarStore& store, std::string& error) {
  static_assert(kLobbyAvatars > 0);
  std::vector<StoredAvatar> faces;
  for (const ResidentFace& resident : resident_faces()) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(resident.package.data());
    auto stored = store.put_own_face({bytes, resident.package.size()}, error);
    if (!stored) {
      error = "the face of the resident " + std::string(resident.name) + " is not a valid package: " + error +
              " (prepare the residents again: cmake --build build --target remake-residents)";
      return std::nullopt;
    }
    faces.push_back(std::move(*stored));
  }
  if (faces.size() != kLobbyAvatars) {
    error = "the lobby seats " + std::to_string(kLobbyAvatars) + " residents, and " + std::to_string(faces.size()) +
            " faces are compiled in";
    return std::nullopt;
  }
  return faces;
}

void open_demo_room(RoomRegistry& rooms, const std::vector<StoredAvatar>& residents, std::function<void()> seated) {
  auto lobby = rooms.find_or_create("lobby", /*persistent=*/true);
  // Opened as a bridge (a cluster), the lobby gets its residents from its owner.
  if (lobby->role() == RoomRoleKind::bridge) return seated();
  seat_lobby_residents(residents, lobby);
  lobby->then(std::move(seated));
}

void seat_lobby_residents(const std::vector<StoredAvatar>& residents, const std::shared_ptr<Room>& lobby) {
  const auto names = resident_faces();  // the first joins first: she leads
  for (std::size_t i = 0; i < residents.size(); ++i) {
    JoinRequest request;
    request.name = std::string(names[i].name);
    request.avatar = residents[i];
    lobby->join(std::move(request));
  }
}

}  // namespace fw::server
