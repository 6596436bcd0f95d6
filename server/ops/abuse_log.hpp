#pragma once
// Refusals and protocol violations, counted by kind for /metrics and logged
// at a bounded rate: an attacker who makes the server refuse a million
// requests must not also fill its disk with a million lines. Thread-safe.
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string_view>

namespace fw::server {

enum class Abuse {
  connection_limit,          ///< the server's connections are all taken
  address_connection_limit,  ///< one address holds its share of connections
  descriptors_exhausted,     ///< accept() failed for want of file descriptors
  handshake_timeout,         ///< no whole request or hello in time
  http_bad_request,          ///< HTTP 4xx answered
  protocol_violation,        ///< malformed or out-of-place room messages, WebSocket violations
  message_rate,              ///< room messages (pings included) over the rate
  join_rate,                 ///< hellos from one address over the rate
  chat_rate,                 ///< chat lines over the address's or the room's rate
  upload_rate,               ///< uploads from one address over the rate
  upload_bytes,              ///< upload bytes in flight over the address's or the server's share
  photo_queue_full,          ///< photos waiting to be prepared at the limit
  room_creation,             ///< rooms created by one address over the rate
  room_seats,                ///< one address holds its share of a room's seats
  idle_person,               ///< a person who neither sent nor read for too long, let go
  not_reading,               ///< a connection whose send queue overflowed
  unauthorized,              ///< a missing, bad or expired token, or a wrong operator secret
  token_in_use,              ///< a token another live session holds
  face_not_yours,            ///< a hello naming an asset, or a deletion of one, without its secret
  bad_name,                  ///< a display name with control, bidi or zero-width characters
  bad_forwarded_header,      ///< a trusted proxy's X-Forwarded-For or Forwarded that names no address
  bad_hello,                 ///< a hello refused for what it asks: room name, unknown avatar, a key without a face
  room_full,                 ///< a room's seats or avatar ids, or the server's rooms, all taken
  shutting_down,             ///< a join while the server drains
  idle_timeout,              ///< a room connection that sent nothing, not even pings, for too long
  upload_too_slow,           ///< an upload's body slower than --min-upload-bytes-per-second, closed with 408
  photo_too_large,           ///< a photo whose header declares more than --max-photo-pixels, refused undecoded
  cluster_message,           ///< a message on the cluster's Redis channels no node of it could have sent
  block_connection_limit,    ///< one network block (/24, /48) holds its share of a port's connections
  connection_evicted,        ///< a connection that had sent nothing useful yet gave its place to a newcomer
  room_share,                ///< an address or its block holds its share of rooms, or only fresh blocks may open one
  script_rate,               ///< face scripts over the connection's or the address's rate
  preview_limit,             ///< an address, or the server, holds its most face-lab previews
  count_,                    ///< not a kind: how many there are
};
inline constexpr std::size_t kAbuseKinds = static_cast<std::size_t>(Abuse::count_);

/// The kind's name in logs and in /metrics' label.
std::string_view abuse_name(Abuse kind);

/// Every line the server writes about one connection goes through here,
/// refusals (note) and ordinary comings and goings (event) alike: whoever
/// can open connections can make such lines, so together they are held to
/// kLinesPerSecond.
class AbuseLog {
 public:
  /// Counts one `kind` refused from `peer`, and logs `what` unless more
  /// than kLinesPerSecond lines went out this second (then the next line
  /// that goes out says how many were left out).
  void note(Abuse kind, std::string_view peer, std::string_view what);
  /// Logs `what` of `peer` at info level (someone joined, left, stored a
  /// face), counting nothing, within the same lines a second as note().
  void event(std::string_view peer, std::string_view what);
  std::uint64_t count(Abuse kind) const { return counts_[static_cast<std::size_t>(kind)].load(); }
  /// Counts `n` of `kind` without a line, for a caller that logs a summary
  /// of many itself (the listener when descriptors run out).
  void count_quietly(Abuse kind, std::uint64_t n) {
    counts_[static_cast<std::size_t>(kind)].fetch_add(n, std::memory_order_relaxed);
  }

  static constexpr int kLinesPerSecond = 20;

 private:
  /// Whether a line may go out now; `left_out` is how many did not since the
  /// last one that did.
  bool may_write(std::uint64_t& left_out);

  std::array<std::atomic<std::uint64_t>, kAbuseKinds> counts_{};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point second_{};
  int lines_this_second_ = 0;
  std::uint64_t suppressed_ = 0;
};

}  // namespace fw::server
