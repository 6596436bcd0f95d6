#pragma once
// What a socket still holds for its peer. A write completes when the kernel
// takes the bytes, so a peer that reads nothing is seen in our own queue
// only after the kernel's send buffer filled too; the socket's send queue
// shows it as soon as the peer's receive buffer is full (ClientSession's
// idle-person rule).
#include <cstddef>
#include <optional>

namespace fw::server {

/// Bytes in the send queue of the socket `fd` that its peer has not
/// acknowledged, sent or not (Linux SIOCOUTQ); nullopt if it cannot tell
/// (closed, not a TCP socket).
std::optional<std::size_t> socket_unacknowledged_bytes(int fd);

}  // namespace fw::server
