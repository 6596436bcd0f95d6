#pragma once
// What a connection refused at accept is sent before it is closed
// (ConnectionAdmission, or no file descriptor left). Its request is not
// read: that would cost the time and memory the refusal is there to save.
// So the answer is short, fixed, and fits any socket buffer at once.
#include <cstddef>
#include <string>

#include "abuse_log.hpp"

namespace fw::server {

/// A person's reason: the address's share (`per_address` connections) is
/// taken, or the server is full.
std::string refusal_reason(Abuse why, std::size_t per_address);

/// An HTTP/1.1 answer that closes the connection: 429 when the address
/// holds its share, 503 when the server is full; both with Retry-After.
/// (A browser's WebSocket sees it as a failed upgrade.)
std::string http_refusal(Abuse why, std::size_t per_address);

/// A length-prefixed closing message (PROTOCOL.md, "Framing on TCP"):
/// rate limited when the address holds its share, server full otherwise.
std::string tcp_refusal(Abuse why, std::size_t per_address);

}  // namespace fw::server
