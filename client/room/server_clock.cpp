#include "server_clock.hpp"

#include <algorithm>

namespace fw::client {

void ServerClock::pong(const codec::Pong& pong, std::uint64_t now_us) {
  if (pong.client_time_us > now_us) return;
  const std::uint64_t round_trip = now_us - pong.client_time_us;
  // The server stamped the pong about half a round trip after the ping left.
  if (round_trip > best_round_trip_us_) return;
  best_round_trip_us_ = round_trip;
  offset_us_ = static_cast<std::int64_t>(pong.server_time_us) -
               static_cast<std::int64_t>(pong.client_time_us + round_trip / 2);
}

std::optional<double> ServerClock::elapsed_ms(std::uint64_t server_time_us, std::uint64_t now_us) const {
  if (!offset_us_) return std::nullopt;
  const double client_tick_us = static_cast<double>(server_time_us) - static_cast<double>(*offset_us_);
  return std::max(0.0, (static_cast<double>(now_us) - client_tick_us) / 1000.0);
}

void ServerClock::reset() {
  offset_us_.reset();
  best_round_trip_us_ = UINT64_MAX;
}

}  // namespace fw::client
