#pragma once
// What a connection refused at accept is sent before it is closed
// (ConnectionAdmission, or no file descriptor left). Its request is not
// read: that would cost the time and memory the refusal is there to save.
// So the answer is short, fixed, and fits any socket buffer at once.
#include <chrono>
#include <cstddef>
#include <string>

#include "abuse_log.hpp"

namespace fw::server {

/// A person's reason, with when to try again: the address's share (`share`
/// connections) is taken, or its network block's (`share` connections), or
/// the server is full.
std::string refusal_reason(Abuse why, std::size_t share, std::chrono::seconds retry_after);

/// An HTTP/1.1 answer that closes the connection: 429 when the address or
/// its block holds its share, 503 when the server is full; both with
/// Retry-After `retry_after`. (A browser's WebSocket sees it as a failed
/// upgrade.)
std::string http_refusal(Abuse why, std::size_t share, std::chrono::seconds retry_after);

/// A length-prefixed closing message (PROTOCOL.md, "Framing on TCP"):
/// rate limited when the address or its block holds its share, server full
/// otherwise; its reason says when to try again.
std::string tcp_refusal(Abuse why, std::size_t share, std::chrono::seconds retry_after);

}  // namespace fw::server
