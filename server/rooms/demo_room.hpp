#pragma once
// The demo: procedural faces for clients without a package, and the room
// "lobby" where three autonomous residents, wearing faces prepared from
// portraits (resident_faces.hpp), reproduce the paper's experiment (the
// first leads, two follow), so a newcomer sees something alive at once.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "avatar_store.hpp"
#include "server_config.hpp"

namespace fw::server {

class Room;
class RoomRegistry;

inline constexpr std::uint32_t kLobbyAvatars = 3;

/// config.demo_faces procedural faces, for clients that join without a
/// package, stored in `store` like uploads (and found there again at the
/// next start); nullopt and `error`, for the person starting the server,
/// when the configuration asks for none or one is refused.
std::optional<std::vector<StoredAvatar>> make_demo_avatars(const ServerConfig& config, AvatarStore& store,
                                                           std::string& error);

/// The lobby's kLobbyAvatars residents' faces, in resident_faces() order,
/// stored in `store` like the demo faces; nullopt and `error` when one is
/// refused (a package the build compiled in is stale: remake-residents).
std::optional<std::vector<StoredAvatar>> store_resident_faces(AvatarStore& store, std::string& error);

/// Opens "lobby" (persistent) in `rooms` with its residents, wearing
/// `residents`; `seated` runs once they sit in it.
/// In a cluster the lobby opens as a bridge, and its residents are seated by
/// the node that first owns it (seat_lobby_residents).
void open_demo_room(RoomRegistry& rooms, const std::vector<StoredAvatar>& residents, std::function<void()> seated);
/// Seats the lobby's residents, wearing `residents`, in `lobby`.
void seat_lobby_residents(const std::vector<StoredAvatar>& residents, const std::shared_ptr<Room>& lobby);

}  // namespace fw::server
