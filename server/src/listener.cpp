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

Listener::Listener(ServerContext& context, net::io_context& ioc, const net::ip::tcp::endpoint& endpoint,
                   SessionFactory factory, Refusal refusal, beast::error_code& ec, const TrustedProxies* proxies)
    : context_(context), ioc_(ioc), acceptor_(net::make_strand(ioc)), pause_(acceptor_.get_executor()),
      factory_(std::move(factory)), refusal_(std::move(refusal)),
      admission_(*context.addresses, limits::kMaxConnections), proxies_(proxies) {
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

void Listener::admit(net::ip::tcp::socket socket) {
  beast::error_code ec;
  const auto remote = socket.remote_endpoint(ec);
  if (ec) return;  // already gone; the socket closes here
  // A trusted proxy carries many people's connections: its own address is
  // no one's share, and the session counts each request's client instead.
  const bool proxied = proxies_ && proxies_->contains(remote.address());
  Admission admission =
      proxied ? admission_.admit_from_trusted_proxy() : admission_.admit(address_key(remote.address()));
  if (!admission.ticket) {
    refuse(socket, admission.refusal);
    const std::string what =
        admission.refusal == Abuse::address_connection_limit
            ? "connection refused: the address holds " + std::to_string(admission_.per_address()) + " already"
            : "connection refused: " + std::to_string(admission_.max_total()) + " connections open on this port";
    context_.abuse.note(admission.refusal, remote.address().to_string(), what);
    return;
  }
  factory_(std::move(socket), std::move(*admission.ticket));
}

void Listener::refuse(net::ip::tcp::socket& socket, Abuse why) {
  beast::error_code ignored;
  const std::string answer = refusal_(why, admission_.per_address());
  socket.non_blocking(true, ignored);
  socket.send(net::buffer(answer), 0, ignored);
  socket.shutdown(net::ip::tcp::socket::shutdown_both, ignored);
  socket.close(ignored);
}

void Listener::on_descriptors_exhausted(const beast::error_code& ec) {
  // The connection that failed is still queued, and so may be more: with
  // the reserve descriptor free, each can be accepted long enough to be
  // told the server is full, instead of waiting in the queue for nothing.
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
      refuse(socket, Abuse::descriptors_exhausted);
      ++refused;
    }
    reserve_.restore();  // may fail if another thread took the descriptor: tried again next time
    if (accept_ec) break;  // nothing waits any more, or no descriptor after all
  }
  // Every refusal is counted; a line goes out at most once a second.
  const auto counted = static_cast<std::uint64_t>(std::max(refused, 1));
  exhaustion_refusals_unlogged_ += counted;
  const auto now = std::chrono::steady_clock::now();
  if (now - exhaustion_logged_ < std::chrono::seconds(1)) {
    context_.abuse.count_quietly(Abuse::descriptors_exhausted, counted);
  } else {
    exhaustion_logged_ = now;
    context_.abuse.count_quietly(Abuse::descriptors_exhausted, counted - 1);  // note() counts the last
    context_.abuse.note(Abuse::descriptors_exhausted, peer,
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
