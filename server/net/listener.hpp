#pragma once
// Accepts TCP connections and hands each to a session factory (HTTP or the
// room protocol over TCP) with its ConnectionTicket: counted against its
// address and in the listener's shares (ConnectionShares) from accept to
// close. A connection past its address's or its block's share, or for
// which the port has no place, is sent a short refusal that says when to
// try again, and closed at once; when the port is full, a newcomer from a
// block that holds fewer takes the place of a connection that had sent
// nothing useful yet. When the process runs out of file descriptors, the
// listener accepts what waits with a descriptor it keeps in reserve: a
// newcomer stays in the place of such a connection, or is refused; then it
// pauses before accepting again, rather than spin on accept(). On the HTTP port, a connection from a
// trusted proxy (--trusted-proxy) is not held to the per-address share at
// accept: the session counts the client its requests name instead.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/error.hpp>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "connection_admission.hpp"
#include "descriptor_reserve.hpp"
#include "trusted_proxies.hpp"

namespace fw::server {

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  /// Starts a session on an accepted socket (already on its own strand);
  /// the session keeps the ticket until its connection closes.
  using SessionFactory = std::function<void(boost::asio::ip::tcp::socket&&, ConnectionTicket&&)>;
  /// What a refused connection is sent before it is closed
  /// (connection_refusal.hpp), given why and the per-address limit.
  using Refusal = std::function<std::string(Abuse why, std::size_t share, std::chrono::seconds retry_after)>;

  /// Opens, binds and listens; `ec` says why not (port in use, no permission).
  /// `proxies`: peers whose sessions read the client's address from their
  /// requests (the HTTP port's), exempt from the per-address share at accept;
  /// null where nothing forwards addresses (the TCP port).
  /// `shares`: the port's places (ConnectionShares). `abuse` counts and logs
  /// the refusals; `addresses` holds each address's connections.
  Listener(AbuseLog& abuse, AddressLimits& addresses, boost::asio::io_context& ioc,
           const boost::asio::ip::tcp::endpoint& endpoint, SessionFactory factory, Refusal refusal,
           ConnectionShareLimits shares, boost::beast::error_code& ec, const TrustedProxies* proxies = nullptr);
  void run();
  void stop();
  /// The bound address, with the real port when 0 was asked for.
  boost::asio::ip::tcp::endpoint local_endpoint() const;

  /// How long accepting pauses after accept() found no descriptor free.
  static constexpr std::chrono::milliseconds kDescriptorBackoff{100};
  /// Waiting connections refused with the reserve descriptor per pause.
  static constexpr int kRefusalsPerBackoff = 16;

 private:
  void do_accept();
  void on_accept(boost::beast::error_code ec, boost::asio::ip::tcp::socket socket);
  /// `must_evict`: accepted with the reserve descriptor, so it stays only
  /// in the place of a connection that gives its place up. False if refused.
  bool admit(boost::asio::ip::tcp::socket socket, bool must_evict = false);
  /// Sends the refusal without waiting (it fits the empty socket buffer) and closes.
  void refuse(boost::asio::ip::tcp::socket& socket, const Admission& admission);
  /// accept() failed for want of descriptors: refuse what waits, then pause.
  void on_descriptors_exhausted(const boost::beast::error_code& ec);
  /// Accepts again after `delay` (a failed accept() would fail again at once).
  void accept_after(std::chrono::milliseconds delay);

  AbuseLog& abuse_;
  boost::asio::io_context& ioc_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer pause_;
  SessionFactory factory_;
  Refusal refusal_;
  ConnectionAdmission admission_;
  const TrustedProxies* proxies_;
  DescriptorReserve reserve_;
  // At most one log line a second about descriptors (AbuseLog counts every refusal).
  std::chrono::steady_clock::time_point exhaustion_logged_{};
  std::uint64_t exhaustion_refusals_unlogged_ = 0;
};

}  // namespace fw::server
