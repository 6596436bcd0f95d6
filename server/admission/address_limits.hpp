#pragma once
// What each peer address (address_key()) holds and may still take: its open
// connections, its upload bytes in flight, and a token bucket for each kind
// of rate limit. Shared by every connection and held across reconnections:
// a client that leaves and joins again finds its buckets as it left them.
// Thread-safe. Entries of addresses that hold nothing and whose buckets are
// full are forgotten, so a flood of addresses costs bounded memory.
#include <array>
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "abuse_limits.hpp"
#include "token_bucket.hpp"

namespace fw::server {

/// look_save counts an address's saved-look changes; avatar_look_save
/// counts one avatar's, under the key avatar_rate_key() makes (whoever
/// holds its key, from any address), on each node alone: it is never in
/// the spending a cluster shares, which names addresses only.
enum class AddressRate { join, chat, upload, room_creation, script, look_save, avatar_look_save };
inline constexpr std::size_t kAddressRateCount = 7;

/// The key an avatar's own rates are counted under (beside address keys,
/// which never start so).
inline std::string avatar_rate_key(const std::string& asset) { return "avatar:" + asset; }

/// The bucket of `rate` under `limits`.
BucketRate rate_of(const AbuseLimits& limits, AddressRate rate);

/// Whether an upload's bytes fit: granted, or whose share is taken.
enum class UploadShare { granted, address_full, server_full };

class AddressLimits {
 public:
  using Clock = std::chrono::steady_clock;

  explicit AddressLimits(const AbuseLimits& limits);

  /// One more connection from `key`; false (and nothing counted) when the
  /// address already holds its share.
  bool open_connection(const std::string& key);
  void close_connection(const std::string& key);
  std::size_t connections(const std::string& key) const;

  /// Takes one token of `rate` for `key`; nullopt if granted, else the
  /// seconds to wait before one is there.
  std::optional<double> take(AddressRate rate, const std::string& key, Clock::time_point now = Clock::now());

  /// Reserves `bytes` of upload body for `key` unless that would take the
  /// address's or the server's share past its limit. An address with no
  /// upload in flight may always start one (if the server's share allows),
  /// and anyone may when the server has none: a share smaller than the
  /// largest upload then holds uploads to one at a time, never refuses one
  /// for good.
  /// Counts bytes as they are received (an upload's body grows its
  /// UploadReservation), never as declared: a body that has not come holds
  /// nothing, so uploads dribbled a byte at a time cannot take the shares.
  UploadShare reserve_upload(const std::string& key, std::size_t bytes);
  /// Whether `bytes` more would fit now, by the same rule, without
  /// reserving them: an upload's declared length, judged from its header.
  UploadShare upload_fits(const std::string& key, std::size_t bytes) const;
  void release_upload(const std::string& key, std::size_t bytes);
  std::size_t upload_bytes() const;

  const AbuseLimits& limits() const { return limits_; }

  // Cluster: the limits hold across nodes (cluster_limits.hpp). Each node
  // tells the others, twice a second, what each address spent here and
  // how many connections it holds here; they take the one from their
  // buckets and add the other to their counts.
  struct Spent {
    std::string key;
    AddressRate rate;
    double tokens = 0;
  };
  /// From now on every token taken here is noted for take_spending().
  void share_spending() { sharing_ = true; }
  /// What was taken here since the last call.
  std::vector<Spent> take_spending();
  //
  // What another node says is news that ages: Redis is open to whoever
  // reaches it, and a node that stops reporting is gone. Spending is taken
  // from the buckets here, but never so much that the address waits longer
  // than `longest_wait` for its next token here; connections count until
  // `expires` unless the node says them again (every beat), and at most
  // the address's share.
  /// Tokens an address spent on another node, taken here too.
  void charge(AddressRate rate, const std::string& key, double tokens, Clock::time_point now,
              std::chrono::duration<double> longest_wait);
  /// Connections open here, by address.
  std::map<std::string, std::size_t> connection_counts() const;
  /// The connections `node` holds, by address; replaces what it said before
  /// (an empty map: it holds none, or left the cluster). At most
  /// kMaxRemoteNodes nodes are heard at once.
  void set_remote_connections(const std::string& node, std::map<std::string, std::size_t> counts,
                              Clock::time_point now = Clock::now(),
                              Clock::time_point expires = Clock::time_point::max());
  static constexpr std::size_t kMaxRemoteNodes = 256;

 private:
  struct Entry {
    std::size_t connections = 0;
    std::size_t upload_bytes = 0;
    std::array<std::optional<TokenBucket>, kAddressRateCount> buckets;
  };
  BucketRate rate_of(AddressRate rate) const;
  /// Whether `bytes` more fit beside the `held` of an address (mutex_ held).
  UploadShare share_for(std::size_t held, std::size_t bytes) const;
  void forget_if_idle(std::map<std::string, Entry>::iterator it, Clock::time_point now);
  /// Forgets every idle entry; amortised over many takes.
  void sweep(Clock::time_point now);

  std::size_t remote_connections(const std::string& key, Clock::time_point now) const;

  AbuseLimits limits_;
  mutable std::mutex mutex_;
  bool sharing_ = false;
  std::map<std::pair<std::string, AddressRate>, double> spent_;
  struct Remote {
    std::map<std::string, std::size_t> counts;  ///< address -> connections
    Clock::time_point expires;
  };
  std::map<std::string, Remote> remote_;  ///< by node
  std::map<std::string, Entry> entries_;
  std::size_t upload_bytes_ = 0;
  std::size_t takes_since_sweep_ = 0;
};

/// One connection counted against its address from accept to close: the
/// session that carries it (through an upgrade too) owns it.
class ConnectionSlot {
 public:
  ConnectionSlot() = default;
  ConnectionSlot(AddressLimits& limits, std::string key) : limits_(&limits), key_(std::move(key)) {}
  ConnectionSlot(ConnectionSlot&& other) noexcept : limits_(other.limits_), key_(std::move(other.key_)) {
    other.limits_ = nullptr;
  }
  ConnectionSlot& operator=(ConnectionSlot&& other) noexcept {
    if (this != &other) {
      release();
      limits_ = other.limits_;
      key_ = std::move(other.key_);
      other.limits_ = nullptr;
    }
    return *this;
  }
  ConnectionSlot(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(const ConnectionSlot&) = delete;
  ~ConnectionSlot() { release(); }

  const std::string& key() const { return key_; }

 private:
  void release() {
    if (limits_) limits_->close_connection(key_);
    limits_ = nullptr;
  }
  AddressLimits* limits_ = nullptr;
  std::string key_;
};

}  // namespace fw::server
