#pragma once
// The server's monotonic clock as the client sees it, learnt from pings:
// the offset (server minus client) from the ping whose round trip was the
// shortest on this connection, since its pong was stamped closest to half
// way. Timed room frames carry the server's time of their tick; with the
// offset, the client knows how long ago that was (the latency figures).
#include <cstdint>
#include <optional>

#include "fw/codec/messages.hpp"

namespace fw::client {

class ServerClock {
 public:
  /// A pong arrived at `now_us` on the client's clock. Pongs from the
  /// future (a clock that went back) are ignored.
  void pong(const codec::Pong& pong, std::uint64_t now_us);
  /// Server minus client clock, microseconds; none before the first pong.
  std::optional<std::int64_t> offset_us() const { return offset_us_; }
  /// Milliseconds from the server's `server_time_us` to the client's
  /// `now_us` (at least 0); none before the first pong.
  std::optional<double> elapsed_ms(std::uint64_t server_time_us, std::uint64_t now_us) const;
  /// A new connection: a new server, perhaps, and another path.
  void reset();

 private:
  std::optional<std::int64_t> offset_us_;
  std::uint64_t best_round_trip_us_ = UINT64_MAX;
};

}  // namespace fw::client
