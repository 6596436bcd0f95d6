#pragma once
// Accepts TCP connections and hands each to a session factory (HTTP or the
// room protocol over TCP), up to the connection limit.
#include <atomic>
#include <functional>
#include <memory>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/error.hpp>

namespace fw::server {

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  /// Starts a session on an accepted socket (already on its own strand);
  /// the counter is the listener's open connections, to be decremented
  /// when the session ends.
  using SessionFactory =
      std::function<void(boost::asio::ip::tcp::socket&&, std::shared_ptr<std::atomic<std::size_t>>)>;
  /// Opens, binds and listens; `ec` says why not (port in use, no permission).
  Listener(boost::asio::io_context& ioc, const boost::asio::ip::tcp::endpoint& endpoint, SessionFactory factory,
           boost::beast::error_code& ec);
  void run();
  void stop();
  /// The bound address, with the real port when 0 was asked for.
  boost::asio::ip::tcp::endpoint local_endpoint() const;

 private:
  void do_accept();
  void on_accept(boost::beast::error_code ec, boost::asio::ip::tcp::socket socket);

  boost::asio::io_context& ioc_;
  boost::asio::ip::tcp::acceptor acceptor_;
  SessionFactory factory_;
  std::shared_ptr<std::atomic<std::size_t>> open_connections_ = std::make_shared<std::atomic<std::size_t>>(0);
};

}  // namespace fw::server
