#pragma once
// Limits per peer address (address_key(): an IPv4 address or an IPv6 /64)
// and per room, held across reconnections, so that one client cannot take
// what belongs to everyone (PROTOCOL.md, "Limits"). ServerConfig::abuse
// holds them; tests and benchmarks that run many clients from one loopback
// address raise them.
#include <cstddef>

#include "server_limits.hpp"
#include "token_bucket.hpp"

namespace fw::server {

struct AbuseLimits {
  /// Connections open at once from one address, from accept to close,
  /// whatever they carry (HTTP, WebSocket, TCP).
  std::size_t connections_per_address = 64;
  /// Hellos from one address (room joins, reconnections included).
  BucketRate joins{1.0, 20};
  /// Chat lines from one address, over all its connections.
  BucketRate chat{2.0, 10};
  /// Face scripts (FACS commands) from one address, over all its
  /// connections: each is read on its room's strand, so a crowd of
  /// connections from one address may not keep rooms reading.
  BucketRate scripts{2.0, 10};
  /// Saved looks written or deleted (PUT and DELETE /api/avatars/ID/looks/NAME)
  /// from one address, and of one avatar from any address: each is a
  /// durable write (and a Redis write in a cluster). The bursts let a
  /// person fill an avatar's 16 looks at once and correct a few; then one
  /// every 10 s.
  BucketRate look_saves{0.1, 32};
  BucketRate avatar_look_saves{0.1, 24};
  /// Chat lines into one room, from everyone in it.
  BucketRate room_chat{5.0, 20};
  /// Joins into one room, from every address together.
  BucketRate room_joins{2.0, 30};
  /// Photo and package uploads from one address.
  BucketRate uploads{6.0 / 60.0, 6};
  /// Rooms one address may create.
  BucketRate room_creations{5.0 / 60.0, 5};
  /// Rooms open at once that one address, and one network block
  /// (address_group(): an IPv4 /24, an IPv6 /48), opened (RoomShares).
  std::size_t rooms_per_address = 5;
  std::size_t rooms_per_block = 20;
  /// Connections one network block may hold on each port (ConnectionShares).
  std::size_t connections_per_block = limits::kMaxConnectionsPerBlock;
  /// The share of rooms, and of each port's connections, kept for
  /// addresses whose block holds none: what a crowd from a few networks
  /// leaves to everyone else, in percent.
  std::size_t fresh_share_percent = 10;
  /// Seats one address may hold in one room; 0: half the room size.
  std::size_t seats_per_address = 0;
  /// Seats one network block may hold in one room; 0: three quarters of the
  /// room size: addresses of one /24 (or /48) together cannot fill a room.
  std::size_t seats_per_block = 0;
  /// Upload body bytes being received at once, from one address and in all.
  std::size_t upload_bytes_per_address = 8 * 1024 * 1024;
  std::size_t upload_bytes_total = 64 * 1024 * 1024;
  /// Photos waiting to be prepared; more are answered 503 with Retry-After.
  std::size_t photo_queue = 8;
};

}  // namespace fw::server
