#pragma once
// The demo: procedural faces for clients without a package, and the room
// "lobby" where three autonomous avatars reproduce the paper's experiment
// (the first leads, two follow), so a newcomer sees something alive at once.
#include <cstdint>
#include <functional>
#include <string>

#include "server_context.hpp"

namespace fw::server {

inline constexpr std::uint32_t kLobbyAvatars = 3;

/// Fills context.demo_avatars with config.demo_faces faces (stored in the
/// avatar store like uploads).
bool make_demo_avatars(ServerContext& context, std::string& error);

/// Opens "lobby" (persistent) with its three avatars; `seated` runs once
/// they sit in it.
void open_demo_room(ServerContext& context, std::function<void()> seated);

}  // namespace fw::server
