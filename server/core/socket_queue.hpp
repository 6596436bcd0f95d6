#pragma once
// What a socket still holds for its peer, and whether the peer has room for
// it. A write completes when the kernel takes the bytes, so a peer that
// reads nothing is seen in our own queue only after the kernel's send
// buffer filled too; the socket shows it as soon as the peer's receive
// buffer is full: bytes wait, and the window the peer advertises (the room
// left in its receive buffer) stays below them. A peer that reads keeps its
// window open, however long its link (ClientSession's idle-person rule).
#include <cstddef>
#include <optional>

namespace fw::server {

struct SocketQueue {
  /// Bytes in the send queue that the peer has not acknowledged, sent or not (SIOCOUTQ).
  std::size_t unacknowledged = 0;
  /// The receive window the peer advertises (TCP_INFO); nullopt on a
  /// kernel that does not say.
  std::optional<std::size_t> peer_window;
};

/// The send queue of the TCP socket `fd`; nullopt if it cannot tell (closed).
std::optional<SocketQueue> socket_queue(int fd);

}  // namespace fw::server
