#include "listener.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core/bind_handler.hpp>
#include <spdlog/spdlog.h>

#include "peer_address.hpp"
#include "server_limits.hpp"

namespace fw::server {

namespace net = boost::asio;
namespace beast = boost::beast;

Listener::Listener(AbuseLog& abuse, AddressLimits& addresses, net::io_context& ioc,
                   const net::ip::tcp::endpoint& endpoint, SessionFactory factory, Refusal refusal,
                   ConnectionShareLimits shares, beast::error_code& ec, const TrustedProxies* proxies)
    : abuse_(abuse), ioc_(ioc), acceptor_(net::make_strand(ioc)), pause_(acceptor_.get_executor()),
      factory_(std::move(factory)), refusal_(std::move(refusal)), admission_(addresses, shares),
      proxies_(proxies) {
  if (acceptor_.open(endpoint.protocol(), ec)) return;
  if (acceptor_.set_option(net::socket_base::reuse_address(true), ec)) return;
  if (acceptor_.bind(endpoint, ec)) return;
  if (acceptor_.listen(net::socket_base::max_listen_connections, ec)) return;
  // The synchronous accept() that refuses with the reserve descriptor must
  // not block when nothing waits; asynchronous accepts are not affected.
  acceptor_.non_blocking(true, ec);
}

void Listener::run() { do_accept(); }

void Listener::stop() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] {
    beast::error_code ignored;
    self->pause_.cancel();
    self->acceptor_.close(ignored);
  });
}

net::ip::tcp::endpoint Listener::local_endpoint() const { return acceptor_.local_endpoint(); }

void Listener::do_accept() {
  // Each connection gets its own strand, so its handlers never run at once.
  acceptor_.async_accept(net::make_strand(ioc_), beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
}

void Listener::on_accept(beast::error_code ec, net::ip::tcp::socket socket) {
  if (ec == net::error::operation_aborted || !acceptor_.is_open()) return;  // stopping
  if (is_descriptor_exhaustion(ec)) return on_descriptors_exhausted(ec);
  if (ec == net::error::connection_aborted) return do_accept();  // the peer gave up while queued
  if (ec) {
    // Anything else (no buffer space, no memory) would fail again at once too.
    spdlog::warn("accept: {}; accepting again in {} ms", ec.message(), kDescriptorBackoff.count());
    return accept_after(kDescriptorBackoff);
  }
  admit(std::move(socket));
  do_accept();
}

bool Listener::admit(net::ip::tcp::socket socket, bool must_evict) {
  beast::error_code ec;
  const auto remote = socket.remote_endpoint(ec);
  if (ec) return false;  // already gone; the socket closes here
  const std::string peer = remote.address().to_string();
  // A trusted proxy carries many people's connections: its own address is
  // no one's share, and the session counts each request's client instead.
  const bool proxied = proxies_ && proxies_->contains(remote.address());
  const auto now = std::chrono::steady_clock::now();
  Admission admission = proxied ? admission_.admit_from_trusted_proxy(now, must_evict)
                                : admission_.admit(address_key(remote.address()), now, must_evict);
  if (!admission.ticket) {
    refuse(socket, admission);
    const std::string again = "; told to try again in " + std::to_string(admission.retry_after.count()) + " s";
    switch (admission.refusal) {
      case Abuse::address_connection_limit:
        abuse_.note(admission.refusal, peer,
                            "connection refused: the address holds " + std::to_string(admission_.per_address()) +
                                " already" + again);
        break;
      case Abuse::block_connection_limit:
        abuse_.note(admission.refusal, peer,
                            "connection refused: its network holds " + std::to_string(admission_.per_block()) +
                                " on this port already" + again);
        break;
      case Abuse::descriptors_exhausted: break;  // counted and logged by the caller, at most once a second
      default:
        abuse_.note(admission.refusal, peer,
                            "connection refused: " + std::to_string(admission_.open()) + " of " +
                                std::to_string(admission_.max_total()) +
                                " connections open on this port, none of them a waiting one from a larger "
                                "network" + again);
    }
    return false;
  }
  if (!admission.evicted.empty())
    abuse_.note(Abuse::connection_evicted, admission.evicted,
                        std::string(must_evict ? "no file descriptor left" : "the port is full") +
                            ": a connection that had sent nothing useful yet gave its place to " + peer);
  factory_(std::move(socket), std::move(*admission.ticket));
  return true;
}

void Listener::refuse(net::ip::tcp::socket& socket, const Admission& admission) {
  beast::error_code ignored;
  const std::size_t share = admission.refusal == Abuse::block_connection_limit ? admission_.per_block()
                                                                               : admission_.per_address();
  const std::string answer = refusal_(admission.refusal, share, admission.retry_after);
  socket.non_blocking(true, ignored);
  socket.send(net::buffer(answer), 0, ignored);
  socket.shutdown(net::ip::tcp::socket::shutdown_both, ignored);
  socket.close(ignored);
}

void Listener::on_descriptors_exhausted(const beast::error_code& ec) {
  // The connection that failed is still queued, and so may be more: with
  // the reserve descriptor free, each can be accepted and looked at. One
  // from a network that holds fewer stays in the place of a connection that
  // had sent nothing useful yet (whose descriptor frees in a moment); the
  // rest are told the server is full and when to try again, instead of
  // waiting in the queue for nothing.
  reserve_.restore();  // if another thread took it last time
  int refused = 0;
  std::string peer = "(no peer)";
  while (refused < kRefusalsPerBackoff && reserve_.release()) {
    net::ip::tcp::socket socket(ioc_);
    beast::error_code accept_ec;
    acceptor_.accept(socket, accept_ec);
    if (!accept_ec) {
      beast::error_code ignored;
      peer = socket.remote_endpoint(ignored).address().to_string();
      if (!admit(std::move(socket), true)) ++refused;
    }
    reserve_.restore();  // may fail if another thread took the descriptor: tried again next time
    if (accept_ec) break;  // nothing waits any more, or no descriptor after all
  }
  // Every refusal is counted; a line goes out at most once a second.
  const auto counted = static_cast<std::uint64_t>(std::max(refused, 1));
  exhaustion_refusals_unlogged_ += counted;
  const auto now = std::chrono::steady_clock::now();
  if (now - exhaustion_logged_ < std::chrono::seconds(1)) {
    abuse_.count_quietly(Abuse::descriptors_exhausted, counted);
  } else {
    exhaustion_logged_ = now;
    abuse_.count_quietly(Abuse::descriptors_exhausted, counted - 1);  // note() counts the last
    abuse_.note(Abuse::descriptors_exhausted, peer,
                        "accept: " + ec.message() + "; " + std::to_string(exhaustion_refusals_unlogged_) +
                            " connection(s) refused since the last line" +
                            (reserve_.held() ? "" : " (no descriptor in reserve)") + "; accepting again every " +
                            std::to_string(kDescriptorBackoff.count()) +
                            " ms. Raise the open-files limit (ulimit -n) or lower --max-connections-per-address");
    exhaustion_refusals_unlogged_ = 0;
  }
  accept_after(kDescriptorBackoff);
}

void Listener::accept_after(std::chrono::milliseconds delay) {
  pause_.expires_after(delay);
  pause_.async_wait([self = shared_from_this()](beast::error_code ec) {
    if (ec || !self->acceptor_.is_open()) return;
    self->do_accept();
  });
}

}  // namespace fw::server
