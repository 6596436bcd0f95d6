#include "abuse_log.hpp"

#include <spdlog/spdlog.h>

namespace fw::server {

std::string_view abuse_name(Abuse kind) {
  static constexpr std::array<std::string_view, kAbuseKinds> kNames = {
      "connection_limit", "address_connection_limit", "descriptors_exhausted", "handshake_timeout",
      "http_bad_request", "protocol_violation",       "message_rate",          "join_rate",
      "chat_rate",        "upload_rate",              "upload_bytes",          "photo_queue_full",
      "room_creation",    "room_seats",               "idle_person",           "not_reading",
      "unauthorized",     "token_in_use",             "face_not_yours",        "bad_name",
      "bad_forwarded_header", "block_connection_limit", "connection_evicted", "room_share"};
  return kNames[static_cast<std::size_t>(kind)];
}

void AbuseLog::note(Abuse kind, std::string_view peer, std::string_view what) {
  counts_[static_cast<std::size_t>(kind)].fetch_add(1, std::memory_order_relaxed);
  std::uint64_t left_out = 0;
  {
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (now - second_ >= std::chrono::seconds(1)) {
      second_ = now;
      lines_this_second_ = 0;
    }
    if (lines_this_second_ >= kLinesPerSecond) {
      ++suppressed_;
      return;
    }
    ++lines_this_second_;
    left_out = suppressed_;
    suppressed_ = 0;
  }
  if (left_out > 0)
    spdlog::warn("refused {} ({}): {} [and {} more refusals not logged]", peer, abuse_name(kind), what, left_out);
  else
    spdlog::warn("refused {} ({}): {}", peer, abuse_name(kind), what);
}

}  // namespace fw::server
