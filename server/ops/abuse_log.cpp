#include "abuse_log.hpp"

#include <spdlog/spdlog.h>

namespace fw::server {

// A switch, not a table: a kind added without its name fails to compile
// (-Werror=switch) instead of shifting every name after it.
std::string_view abuse_name(Abuse kind) {
  switch (kind) {
    case Abuse::connection_limit: return "connection_limit";
    case Abuse::address_connection_limit: return "address_connection_limit";
    case Abuse::descriptors_exhausted: return "descriptors_exhausted";
    case Abuse::handshake_timeout: return "handshake_timeout";
    case Abuse::http_bad_request: return "http_bad_request";
    case Abuse::protocol_violation: return "protocol_violation";
    case Abuse::message_rate: return "message_rate";
    case Abuse::join_rate: return "join_rate";
    case Abuse::chat_rate: return "chat_rate";
    case Abuse::upload_rate: return "upload_rate";
    case Abuse::upload_bytes: return "upload_bytes";
    case Abuse::photo_queue_full: return "photo_queue_full";
    case Abuse::room_creation: return "room_creation";
    case Abuse::room_seats: return "room_seats";
    case Abuse::idle_person: return "idle_person";
    case Abuse::not_reading: return "not_reading";
    case Abuse::unauthorized: return "unauthorized";
    case Abuse::token_in_use: return "token_in_use";
    case Abuse::face_not_yours: return "face_not_yours";
    case Abuse::bad_name: return "bad_name";
    case Abuse::bad_forwarded_header: return "bad_forwarded_header";
    case Abuse::bad_hello: return "bad_hello";
    case Abuse::room_full: return "room_full";
    case Abuse::shutting_down: return "shutting_down";
    case Abuse::idle_timeout: return "idle_timeout";
    case Abuse::upload_too_slow: return "upload_too_slow";
    case Abuse::photo_too_large: return "photo_too_large";
    case Abuse::cluster_message: return "cluster_message";
    case Abuse::block_connection_limit: return "block_connection_limit";
    case Abuse::connection_evicted: return "connection_evicted";
    case Abuse::room_share: return "room_share";
    case Abuse::script_rate: return "script_rate";
    case Abuse::preview_limit: return "preview_limit";
    case Abuse::count_: break;
  }
  return "unknown";
}

bool AbuseLog::may_write(std::uint64_t& left_out) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (now - second_ >= std::chrono::seconds(1)) {
    second_ = now;
    lines_this_second_ = 0;
  }
  if (lines_this_second_ >= kLinesPerSecond) {
    ++suppressed_;
    return false;
  }
  ++lines_this_second_;
  left_out = suppressed_;
  suppressed_ = 0;
  return true;
}

void AbuseLog::note(Abuse kind, std::string_view peer, std::string_view what) {
  counts_[static_cast<std::size_t>(kind)].fetch_add(1, std::memory_order_relaxed);
  std::uint64_t left_out = 0;
  if (!may_write(left_out)) return;
  if (left_out > 0)
    spdlog::warn("refused {} ({}): {} [and {} more lines not logged]", peer, abuse_name(kind), what, left_out);
  else
    spdlog::warn("refused {} ({}): {}", peer, abuse_name(kind), what);
}

void AbuseLog::event(std::string_view peer, std::string_view what) {
  std::uint64_t left_out = 0;
  if (!may_write(left_out)) return;
  if (left_out > 0)
    spdlog::info("{}: {} [and {} more lines not logged]", peer, what, left_out);
  else
    spdlog::info("{}: {}", peer, what);
}

}  // namespace fw::server
