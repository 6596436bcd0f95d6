#pragma once
// Who holds one port's connections, by network block (address_group()),
// and which connection gives its place up when the port is full. Limits
// per address alone let a few dozen addresses hold every place of a port
// (42 addresses half-sending requests held the 2,048 for as long as the
// header deadline, again and again). So:
//  - one block holds at most `per_block` of the port's connections;
//  - the last `fresh_reserve` places go only to blocks that hold none;
//  - when a newcomer finds no place it may have, a connection that has
//    sent nothing useful yet (a request header not complete, a keep-alive
//    waiting for its next request, a WebSocket or TCP connection before its
//    hello) gives its place up, taken from the block that holds the most,
//    and only for a newcomer whose block holds fewer: the crowd is refused,
//    a person on a fresh address is not.
// A refusal says how long until a place frees: the earliest deadline of
// what holds the places it is waiting for, not a guess.
// Thread-safe; time is passed in, so that the decisions are tested without
// sockets (connection_admission_test.cpp).
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "abuse_log.hpp"
#include "server_limits.hpp"

namespace fw::server {

struct ConnectionShareLimits {
  /// Connections open at once on the port.
  std::size_t max_total = limits::kMaxConnections;
  /// Connections one network block may hold on the port.
  std::size_t per_block = limits::kMaxConnectionsPerBlock;
  /// Places only a block that holds none may take.
  std::size_t fresh_reserve = limits::kMaxConnections / 10;
};

class ConnectionShares {
 public:
  using Clock = std::chrono::steady_clock;
  using Id = std::uint64_t;

  /// The answer to one newcomer.
  struct Verdict {
    Id id = 0;  ///< 0: refused
    Abuse refusal = Abuse::connection_limit;
    /// Refused: seconds until a place it may have frees, at least 1.
    std::chrono::seconds retry_after{0};
    /// Admitted in the place of this connection's peer (empty: no one's).
    std::string evicted;
  };

  explicit ConnectionShares(ConnectionShareLimits limits) : limits_(limits) {}

  /// A place for a connection from `address` in `block`, taking one from a
  /// connection that waits if it must. `block` "" is a trusted proxy's
  /// connection: held to no block's share. `must_evict`: the process has no
  /// descriptor left, so the newcomer may stay only in someone's place.
  Verdict admit(const std::string& address, const std::string& block, Clock::time_point now, bool must_evict = false);
  /// The connection waits for its peer to say something useful (a request's
  /// header, a hello) from `now` until `deadline`: it may give its place up
  /// (of a block's waiting connections, the one waiting longest first).
  void waiting(Id id, Clock::time_point now, Clock::time_point deadline);
  /// The connection carries something useful until `deadline`
  /// (Clock::time_point::max(): as long as it lives): it keeps its place.
  void busy(Id id, Clock::time_point deadline);
  /// What closes the connection when it gives its place up (called at once,
  /// outside the lock, if it has already).
  void on_evict(Id id, std::function<void()> evict);
  /// The connection closed.
  void release(Id id);

  std::size_t open() const;
  std::size_t held_by_block(const std::string& block) const;
  /// Seconds until one of `address`'s connections here reaches its deadline
  /// (for the refusal of an address that holds its share).
  std::chrono::seconds retry_for_address(const std::string& address, Clock::time_point now) const;
  const ConnectionShareLimits& limits() const { return limits_; }

  /// When nothing that holds the places has a deadline (people in rooms),
  /// a refusal says this.
  static constexpr std::chrono::seconds kUnknownWait{60};

 private:
  struct Entry {
    std::string address, block;
    Clock::time_point since;     ///< when it began to wait (or was accepted)
    Clock::time_point deadline;  ///< when it closes unless it does something
    bool waiting = true;
    bool evicted = false;
    std::function<void()> evict;
  };
  /// The waiting connection to give its place to a newcomer from a block
  /// that holds `newcomer_holds`: from the block that holds the most (more
  /// than the newcomer's would with it), the one waiting longest. Caller holds mutex_.
  std::map<Id, Entry>::iterator victim(std::size_t newcomer_holds);
  /// Caller holds mutex_.
  std::chrono::seconds wait_until_free(Clock::time_point now, const std::string* block) const;
  void forget(std::map<Id, Entry>::iterator it);

  ConnectionShareLimits limits_;
  mutable std::mutex mutex_;
  std::map<Id, Entry> entries_;
  std::map<std::string, std::size_t> blocks_;  ///< block -> connections it holds (evicted ones not)
  std::size_t open_ = 0;                       ///< evicted ones not counted
  Id next_id_ = 1;
};

}  // namespace fw::server
