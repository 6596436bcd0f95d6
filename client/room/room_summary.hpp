#pragma once
// The `--json` summary of a join: the link statistics plus what the room
// looked like at the end (avatars, packages, events, the server's view of
// the link).
#include <chrono>

#include <nlohmann/json.hpp>

#include "room_state.hpp"

namespace fw::client {

/// The summary object; the caller holds `state.mutex`.
nlohmann::json room_summary(const RoomState& state, std::chrono::steady_clock::time_point now);

}  // namespace fw::client
