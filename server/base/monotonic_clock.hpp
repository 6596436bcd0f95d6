#pragma once
// The server's monotonic clock in microseconds: timed room frames and pongs
// carry it, so clients on the same host compare it with their own.
#include <chrono>
#include <cstdint>

namespace fw::server {

inline std::uint64_t monotonic_us() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
          .count());
}

}  // namespace fw::server
