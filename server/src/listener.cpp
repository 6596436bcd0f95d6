#include "listener.hpp"

#include <boost/asio/strand.hpp>
#include <boost/beast/core/bind_handler.hpp>
#include <spdlog/spdlog.h>

#include "server_limits.hpp"

namespace fw::server {

namespace net = boost::asio;
namespace beast = boost::beast;

Listener::Listener(net::io_context& ioc, const net::ip::tcp::endpoint& endpoint, SessionFactory factory,
                   beast::error_code& ec)
    : ioc_(ioc), acceptor_(net::make_strand(ioc)), factory_(std::move(factory)) {
  if (acceptor_.open(endpoint.protocol(), ec)) return;
  if (acceptor_.set_option(net::socket_base::reuse_address(true), ec)) return;
  if (acceptor_.bind(endpoint, ec)) return;
  acceptor_.listen(net::socket_base::max_listen_connections, ec);
}

void Listener::run() { do_accept(); }

void Listener::stop() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] {
    beast::error_code ignored;
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
  if (ec) {
    spdlog::warn("accept: {}", ec.message());
  } else if (open_connections_->load() >= limits::kMaxConnections) {
    spdlog::warn("connection limit {} reached; refusing {}", limits::kMaxConnections,
                 socket.remote_endpoint(ec).address().to_string());
  } else {
    ++*open_connections_;
    factory_(std::move(socket), open_connections_);
  }
  do_accept();
}

}  // namespace fw::server
