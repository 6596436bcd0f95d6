#pragma once
// Limits on everything a peer sends the server. A request past any of them
// is answered with an error status (HTTP) or a closing message (rooms) and
// its connection closed; nobody else is affected. PROTOCOL.md, "Limits".
#include <chrono>
#include <cstddef>

namespace fw::server::limits {

inline constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
/// Bodies of requests other than uploads (uploads: ServerConfig::max_upload_bytes).
inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;
/// Time allowed to send one whole request, and to take one response.
inline constexpr std::chrono::seconds kRequestTimeout{15};
/// Time allowed for a request's header (the first request of a connection,
/// a WebSocket upgrade included: from accept; a later one: from its first
/// byte). A fixed deadline: dribbling bytes does not extend it.
inline constexpr std::chrono::seconds kHeaderTimeout{10};
/// Time allowed for an upload's body when no pace is required
/// (--min-upload-bytes-per-second 0): a 4 MiB photo at 2.5 Mbit/s.
inline constexpr std::chrono::seconds kUploadTimeout{15};
/// The window over which an upload's body must keep its pace
/// (--min-upload-bytes-per-second); the body's first window is free.
inline constexpr std::chrono::seconds kUploadPaceWindow{5};
/// After an answer that closes the connection, what the peer still sends
/// (the rest of a refused upload) is read and dropped for at most this long
/// before the socket closes: closing it with unread bytes would reset the
/// connection, and a browser would then show the reset, not the answer.
inline constexpr std::chrono::seconds kLingerTimeout{3};
inline constexpr std::size_t kMaxLingerBytes = 32 * 1024 * 1024;
/// An idle keep-alive connection is closed after this.
inline constexpr std::chrono::seconds kIdleTimeout{30};
/// Connections open at once on each port, from accept to close (HTTP,
/// WebSocket and TCP, greeting or in a room); more are refused.
inline constexpr std::size_t kMaxConnections = 2048;
/// Of those, what one network block (address_group(): an IPv4 /24, an IPv6
/// /48) may hold: eight blocks, not one, to fill a port.
inline constexpr std::size_t kMaxConnectionsPerBlock = 256;

// Room connections.
inline constexpr std::chrono::seconds kHandshakeTimeout{5};
inline constexpr std::chrono::seconds kSessionIdleTimeout{60};
/// A person who sends nothing but pings and reads nothing is let go after
/// this (--idle-seat-seconds): their seat, and a room only they hold, go
/// to someone who is there.
inline constexpr std::chrono::minutes kIdlePersonTimeout{2};
/// An avatar id rests this long after its avatar left before a newcomer gets it.
inline constexpr std::chrono::seconds kAvatarIdQuiet{60};
/// How long a closing message may take before the socket is closed anyway.
inline constexpr std::chrono::seconds kCloseTimeout{3};
/// After a closing message for something the peer did (a flood, a
/// violation, silence), how long the socket stays half-closed, unread,
/// before it closes: time for the message to arrive, none for reading more
/// of a flood.
inline constexpr std::chrono::milliseconds kQuickCloseLinger{500};
inline constexpr double kMessagesPerSecond = 50;
inline constexpr double kMessageBurst = 100;
inline constexpr double kUpstreamBytesPerSecond = 64 * 1024;
inline constexpr double kUpstreamByteBurst = 64 * 1024;
inline constexpr double kChatLinesPerSecond = 2;
inline constexpr double kChatBurst = 5;
/// Face scripts (FACS commands, PROTOCOL.md 5.5) from one connection: each
/// is a performance of seconds, so one a second is more than a person
/// plays; the burst lets a few be tried in a row after a typo.
inline constexpr double kScriptsPerSecond = 1;
inline constexpr double kScriptBurst = 3;
/// Kernel send buffer of a room connection (Linux doubles it).
inline constexpr int kSocketSendBufferBytes = 16 * 1024;
/// Messages held between a hello and its welcome.
inline constexpr std::size_t kMaxEarlyMessages = 16;
/// A connection holding more than this is not reading: it is closed. Room
/// frames and packages stop at half a second of budget, far below.
inline constexpr std::size_t kMaxQueuedBytes = 256 * 1024;

}  // namespace fw::server::limits
