#pragma once
// Whether an accepted connection may stay. Every connection counts, from
// accept to close, against its address (AbuseLimits::connections_per_address)
// and in its listener's total (limits::kMaxConnections), whatever it carries
// and however far it got: still sending its first request, upgraded to a
// WebSocket, greeting or in a room. The session that carries the connection
// owns its ticket (HttpSession hands it to the WebSocketSession it upgrades
// to); the counts drop when the ticket goes. A connection from a trusted
// proxy (--trusted-proxy) counts against the client its request's header
// names instead, from that header on.
#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "abuse_log.hpp"
#include "address_limits.hpp"

namespace fw::server {

/// One connection counted in a listener's total and against its address.
class ConnectionTicket {
 public:
  ConnectionTicket() = default;
  ConnectionTicket(ConnectionSlot address, std::shared_ptr<std::atomic<std::size_t>> total)
      : address_(std::move(address)), total_(std::move(total)) {}
  ConnectionTicket(ConnectionTicket&& other) noexcept = default;
  ConnectionTicket& operator=(ConnectionTicket&& other) noexcept {
    if (this != &other) {
      release_total();
      address_ = std::move(other.address_);
      total_ = std::move(other.total_);
    }
    return *this;
  }
  ConnectionTicket(const ConnectionTicket&) = delete;
  ConnectionTicket& operator=(const ConnectionTicket&) = delete;
  ~ConnectionTicket() { release_total(); }

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

 private:
  void release_total() {
    if (total_) total_->fetch_sub(1);
    total_.reset();
  }
  ConnectionSlot address_;
  std::shared_ptr<std::atomic<std::size_t>> total_;
};

/// The answer to one accepted connection: a ticket, or why it is refused.
struct Admission {
  std::optional<ConnectionTicket> ticket;
  Abuse refusal = Abuse::connection_limit;  ///< when there is no ticket
};

/// Admits connections on one listener. Thread-safe.
class ConnectionAdmission {
 public:
  ConnectionAdmission(AddressLimits& addresses, std::size_t max_total) : addresses_(addresses), max_total_(max_total) {}

  /// A ticket for a connection from `address_key`, unless the listener holds
  /// `max_total` connections (Abuse::connection_limit) or the address its
  /// share (Abuse::address_connection_limit).
  Admission admit(const std::string& address_key);
  /// A ticket for a connection from a trusted proxy: counted in the total
  /// only, since the proxy carries many people's connections; whom it
  /// carries is counted once a request's header says (count_against()).
  Admission admit_from_trusted_proxy();

  std::size_t open() const { return total_->load(); }
  std::size_t max_total() const { return max_total_; }
  std::size_t per_address() const { return addresses_.limits().connections_per_address; }

 private:
  AddressLimits& addresses_;
  std::size_t max_total_;
  std::shared_ptr<std::atomic<std::size_t>> total_ = std::make_shared<std::atomic<std::size_t>>(0);
};

}  // namespace fw::server
