#include "socket_transport.hpp"

#include <array>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/websocket.hpp>

#include "fw/codec/messages.hpp"

namespace fw::client {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class WebSocketTransport : public MessageTransport {
 public:
  WebSocketTransport(asio::io_context& io, ServerUrl url) : url_(std::move(url)), resolver_(io), ws_(io) {}

  void connect(int timeout_s, Done done) override {
    resolver_.async_resolve(url_.host, url_.port, [this, self = shared_from_this(), timeout_s, done](boost::system::error_code ec, tcp::resolver::results_type results) {
      if (ec) return done(ec);
      beast::get_lowest_layer(ws_).expires_after(std::chrono::seconds(timeout_s));
      beast::get_lowest_layer(ws_).async_connect(results, [this, self = shared_from_this(), done](boost::system::error_code connect_ec, const tcp::endpoint&) {
        if (connect_ec) return done(connect_ec);
        configure_stream();
        ws_.async_handshake(url_.host + ":" + url_.port, url_.path, [done](boost::system::error_code handshake_ec) {
          done(handshake_ec);
        });
      });
    });
  }

  void read(Received received) override {
    buffer_.clear();
    ws_.async_read(buffer_, [this, self = shared_from_this(), received](boost::system::error_code ec, std::size_t) {
      if (ec) return received(ec, {});
      const auto data = buffer_.cdata();
      received(ec, {static_cast<const std::uint8_t*>(data.data()), data.size()});
    });
  }

  void write(std::shared_ptr<const std::vector<std::uint8_t>> message, Done done) override {
    ws_.async_write(asio::buffer(*message), [self = shared_from_this(), message, done](boost::system::error_code ec, std::size_t) { done(ec); });
  }

  void close() override {
    boost::system::error_code ignored;
    resolver_.cancel();
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }

  std::size_t framing_bytes(std::size_t message_bytes, bool upstream) const override {
    // RFC 6455 header: 2 bytes, +2 or +8 for longer payloads, +4 mask upstream.
    const std::size_t length = message_bytes < 126 ? 0 : message_bytes < 65536 ? 2 : 8;
    return 2 + length + (upstream ? 4 : 0);
  }

 private:
  // Once the socket is connected: from here on Beast's own timers (the
  // handshake's, and an idle limit with keep-alive pings, so a dead link is
  // noticed), binary messages up to the protocol's limit.
  void configure_stream() {
    beast::get_lowest_layer(ws_).socket().set_option(tcp::no_delay(true));
    beast::get_lowest_layer(ws_).expires_never();
    websocket::stream_base::timeout timeouts = websocket::stream_base::timeout::suggested(beast::role_type::client);
    timeouts.idle_timeout = std::chrono::seconds(20);
    timeouts.keep_alive_pings = true;
    ws_.set_option(timeouts);
    ws_.set_option(websocket::stream_base::decorator([](websocket::request_type& request) {
      request.set(beast::http::field::user_agent, "facewire-client");
    }));
    ws_.read_message_max(codec::kMaxDownstreamMessageBytes);
    ws_.binary(true);
  }

  ServerUrl url_;
  tcp::resolver resolver_;
  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
};

class TcpTransport : public MessageTransport {
 public:
  TcpTransport(asio::io_context& io, ServerUrl url)
      : url_(std::move(url)), resolver_(io), stream_(io), deframer_(codec::kMaxDownstreamMessageBytes) {}

  void connect(int timeout_s, Done done) override {
    resolver_.async_resolve(url_.host, url_.port, [this, self = shared_from_this(), timeout_s, done](boost::system::error_code ec, tcp::resolver::results_type results) {
      if (ec) return done(ec);
      stream_.expires_after(std::chrono::seconds(timeout_s));
      stream_.async_connect(results, [this, self = shared_from_this(), done](boost::system::error_code connect_ec, const tcp::endpoint&) {
        stream_.expires_never();
        if (!connect_ec) stream_.socket().set_option(tcp::no_delay(true));
        done(connect_ec);
      });
    });
  }

  void read(Received received) override {
    std::span<const std::uint8_t> message;
    switch (deframer_.next(message)) {
      case codec::TcpDeframer::Status::message:
        return received({}, message);
      case codec::TcpDeframer::Status::error:
        return received(asio::error::make_error_code(asio::error::message_size), {});
      case codec::TcpDeframer::Status::need_more:
        break;
    }
    stream_.async_read_some(asio::buffer(chunk_), [this, self = shared_from_this(), received](boost::system::error_code ec, std::size_t n) {
      if (ec) return received(ec, {});
      deframer_.feed({chunk_.data(), n});
      read(received);
    });
  }

  void write(std::shared_ptr<const std::vector<std::uint8_t>> message, Done done) override {
    auto framed = std::make_shared<std::vector<std::uint8_t>>();
    codec::write_tcp_frame(*message, *framed);
    asio::async_write(stream_, asio::buffer(*framed), [self = shared_from_this(), framed, done](boost::system::error_code ec, std::size_t) { done(ec); });
  }

  void close() override {
    boost::system::error_code ignored;
    resolver_.cancel();
    stream_.socket().close(ignored);
  }

  std::size_t framing_bytes(std::size_t message_bytes, bool) const override {
    std::vector<std::uint8_t> prefix;
    codec::write_length_prefix(message_bytes, prefix);
    return prefix.size();
  }

 private:
  ServerUrl url_;
  tcp::resolver resolver_;
  beast::tcp_stream stream_;
  codec::TcpDeframer deframer_;
  std::array<std::uint8_t, 16 * 1024> chunk_{};
};

}  // namespace

std::shared_ptr<MessageTransport> make_socket_transport(asio::io_context& io, const ServerUrl& url) {
  if (url.scheme == ServerUrl::Scheme::tcp) return std::make_shared<TcpTransport>(io, url);
  return std::make_shared<WebSocketTransport>(io, url);
}

}  // namespace fw::client
