#pragma once
// Limits on everything a peer sends the server. A request past any of them
// is answered with an error status and its connection closed.
#include <chrono>
#include <cstddef>

namespace fw::server::limits {

inline constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
/// Requests carry no bodies yet (uploads arrive with the room server).
inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;
/// Time allowed to send one whole request, and to take one response.
inline constexpr std::chrono::seconds kRequestTimeout{15};
/// An idle keep-alive connection is closed after this.
inline constexpr std::chrono::seconds kIdleTimeout{30};
/// Connections served at once; more wait in the kernel's backlog.
inline constexpr std::size_t kMaxConnections = 2048;

}  // namespace fw::server::limits
