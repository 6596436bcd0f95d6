#pragma once
// The demo: procedural faces for clients without a package, and the room
// "lobby" where three autonomous avatars reproduce the paper's experiment
// (the first leads, two follow), so a newcomer sees something alive at once.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "server_context.hpp"

namespace fw::server {

class Room;

inline constexpr std::uint32_t kLobbyAvatars = 3;

/// Fills context.demo_avatars with config.demo_faces faces (stored in the
/// avatar store like uploads).
bool make_demo_avatars(ServerContext& context, std::string& error);
/// The procedural face of a person who wears no uploaded avatar, chosen by
/// their name so that it stays the same; also the face shown in place of
/// an avatar its uploader deleted. One of context.demo_avatars.
const StoredAvatar& procedural_face_for(const ServerContext& context, const std::string& name);

/// Opens "lobby" (persistent) with its three avatars; `seated` runs once
/// they sit in it.
/// In a cluster the lobby opens as a bridge, and its three avatars are
/// seated by the node that first owns it (seat_lobby_residents).
void open_demo_room(ServerContext& context, std::function<void()> seated);
/// Seats the lobby's three avatars in `lobby`.
void seat_lobby_residents(ServerContext& context, const std::shared_ptr<Room>& lobby);

}  // namespace fw::server
