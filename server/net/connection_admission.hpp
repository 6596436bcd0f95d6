#pragma once
// Whether an accepted connection may stay. Every connection counts, from
// accept to close, against its address (AbuseLimits::connections_per_address)
// and in its listener's shares (ConnectionShares: the port's total, its
// block's share, the places kept for fresh blocks), whatever it carries
// and however far it got: still sending its first request, upgraded to a
// WebSocket, greeting or in a room. The session that carries the connection
// owns its ticket (HttpSession hands it to the WebSocketSession it upgrades
// to); the counts drop when the ticket goes. A connection from a trusted
// proxy (--trusted-proxy) counts against the client its request's header
// names instead, from that header on.
#include <chrono>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "connection_shares.hpp"

namespace fw::server {

/// One connection counted in its listener's shares (ConnectionShares) and
/// against its address.
class ConnectionTicket {
 public:
  using Clock = std::chrono::steady_clock;

  ConnectionTicket() = default;
  ConnectionTicket(ConnectionSlot address, std::shared_ptr<ConnectionShares> shares, ConnectionShares::Id id)
      : address_(std::move(address)), shares_(std::move(shares)), id_(id) {}
  ConnectionTicket(ConnectionTicket&& other) noexcept
      : address_(std::move(other.address_)), shares_(std::move(other.shares_)), id_(other.id_) {
    other.shares_.reset();
  }
  ConnectionTicket& operator=(ConnectionTicket&& other) noexcept {
    if (this != &other) {
      release_place();
      address_ = std::move(other.address_);
      shares_ = std::move(other.shares_);
      id_ = other.id_;
      other.shares_.reset();
    }
    return *this;
  }
  ConnectionTicket(const ConnectionTicket&) = delete;
  ConnectionTicket& operator=(const ConnectionTicket&) = delete;
  ~ConnectionTicket() { release_place(); }

  /// The address key the connection counts against ("" for an empty ticket,
  /// and for a trusted proxy's connection between its requests).
  const std::string& address() const { return address_.key(); }

  /// Counts the connection against `key` instead (the client a trusted
  /// proxy forwards, known once a request's header is read); false, and
  /// the ticket as it was, when that address already holds its share.
  bool count_against(AddressLimits& limits, const std::string& key) {
    if (key == address_.key()) return true;
    if (!limits.open_connection(key)) return false;
    address_ = ConnectionSlot(limits, key);
    return true;
  }
  /// Counts the connection against no address any more (only in the total):
  /// a trusted proxy's connection between two requests, which may be two
  /// different clients'.
  void release_address() { address_ = ConnectionSlot(); }

  /// The connection waits for its peer to say something useful until
  /// `deadline`: when the port is full it may give its place up to a
  /// newcomer (ConnectionShares).
  void waiting(Clock::time_point deadline) {
    if (shares_) shares_->waiting(id_, Clock::now(), deadline);
  }
  /// The connection carries something useful (until `deadline`, when it
  /// closes unless more comes): it keeps its place.
  void busy(Clock::time_point deadline = Clock::time_point::max()) {
    if (shares_) shares_->busy(id_, deadline);
  }
  /// How the session closes the connection when it gives its place up; it
  /// may be called from any thread, and at once.
  void on_evict(std::function<void()> evict) {
    if (shares_) shares_->on_evict(id_, std::move(evict));
  }

 private:
  void release_place() {
    if (shares_) shares_->release(id_);
    shares_.reset();
  }
  ConnectionSlot address_;
  std::shared_ptr<ConnectionShares> shares_;
  ConnectionShares::Id id_ = 0;
};

/// The answer to one accepted connection: a ticket, or why it is refused.
struct Admission {
  std::optional<ConnectionTicket> ticket;
  Abuse refusal = Abuse::connection_limit;  ///< when there is no ticket
  /// When there is no ticket: how long until a place it may have frees
  /// (the earliest deadline of what holds them).
  std::chrono::seconds retry_after{0};
  /// When the ticket took the place of a connection that waited: its peer.
  std::string evicted;
};

/// Admits connections on one listener. Thread-safe.
class ConnectionAdmission {
 public:
  using Clock = std::chrono::steady_clock;

  /// `max_total` places, held to no block's share and with none in reserve.
  ConnectionAdmission(AddressLimits& addresses, std::size_t max_total)
      : ConnectionAdmission(addresses, ConnectionShareLimits{max_total, std::numeric_limits<std::size_t>::max(), 0}) {}
  ConnectionAdmission(AddressLimits& addresses, ConnectionShareLimits shares)
      : addresses_(addresses), shares_(std::make_shared<ConnectionShares>(shares)) {}

  /// A ticket for a connection from `address_key`, unless the address holds
  /// its share (Abuse::address_connection_limit), its block its share
  /// (Abuse::block_connection_limit), or the listener has no place for it
  /// (Abuse::connection_limit; ConnectionShares). `must_evict`: no file
  /// descriptor is left, so it may only take the place of one that waits
  /// (Abuse::descriptors_exhausted when there is none).
  Admission admit(const std::string& address_key, Clock::time_point now = Clock::now(), bool must_evict = false);
  /// A ticket for a connection from a trusted proxy: held to no address's
  /// or block's share, since the proxy carries many people's connections;
  /// whom it carries is counted once a request's header says (count_against()).
  Admission admit_from_trusted_proxy(Clock::time_point now = Clock::now(), bool must_evict = false);

  std::size_t open() const { return shares_->open(); }
  std::size_t max_total() const { return shares_->limits().max_total; }
  std::size_t per_address() const { return addresses_.limits().connections_per_address; }
  std::size_t per_block() const { return shares_->limits().per_block; }
  const ConnectionShares& shares() const { return *shares_; }

 private:
  AddressLimits& addresses_;
  std::shared_ptr<ConnectionShares> shares_;
};

}  // namespace fw::server
