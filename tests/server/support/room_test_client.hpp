#pragma once
// A room-protocol client for the server tests: WebSocket or length-prefixed
// TCP, synchronous calls with time-outs (an io_context run for a while), and
// the bookkeeping the tests check (room_inbox.hpp).
#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"
#include "room_inbox.hpp"

namespace fw::test {

class RoomTestClient : public RoomInbox {
 public:
  enum class Transport { websocket, tcp };

  /// `from`: the local address to connect from (127.0.0.2 and up stand in
  /// for other clients' addresses); empty: the kernel's choice, 127.0.0.1.
  /// `x_forwarded_for`: that header on the WebSocket upgrade (as a proxy
  /// would send it); empty: none.
  RoomTestClient(Transport transport, int port, const std::string& from = "", const std::string& x_forwarded_for = "")
      : transport_(transport), socket_(ioc_), ws_(ioc_) {
    namespace net = boost::asio;
    const net::ip::tcp::endpoint endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port));
    boost::system::error_code ec;
    auto& socket = transport_ == Transport::tcp ? socket_ : boost::beast::get_lowest_layer(ws_).socket();
    if (!from.empty()) {
      socket.open(net::ip::tcp::v4(), ec);
      if (!ec) socket.bind({net::ip::make_address(from), 0}, ec);
    }
    if (!ec) socket.connect(endpoint, ec);
    if (!ec && transport_ == Transport::websocket) {
      ws_.binary(true);
      if (!x_forwarded_for.empty())
        ws_.set_option(boost::beast::websocket::stream_base::decorator(
            [x_forwarded_for](boost::beast::websocket::request_type& request) {
              request.set("X-Forwarded-For", x_forwarded_for);
            }));
      ws_.handshake("127.0.0.1", "/ws", ec);
    }
    connected_ = !ec;
  }

  bool connected() const { return connected_; }
  /// Shrinks the kernel's receive buffer (before anything is read), so that
  /// a client that stops reading pushes back on the server quickly.
  void shrink_receive_buffer(int bytes) {
    boost::asio::socket_base::receive_buffer_size option(bytes);
    boost::system::error_code ec;
    if (transport_ == Transport::tcp) socket_.set_option(option, ec);
    else boost::beast::get_lowest_layer(ws_).socket().set_option(option, ec);
  }

  void send(const std::vector<std::uint8_t>& message) {
    boost::system::error_code ec;
    if (transport_ == Transport::websocket) {
      ws_.write(boost::asio::buffer(message), ec);
    } else {
      std::vector<std::uint8_t> framed;
      codec::write_tcp_frame(message, framed);
      boost::asio::write(socket_, boost::asio::buffer(framed), ec);
    }
    if (ec) send_failed_ = true;
  }
  /// Bytes exactly as given (TCP: no prefix added).
  void send_raw(const std::vector<std::uint8_t>& bytes) {
    boost::system::error_code ec;
    boost::asio::write(socket_, boost::asio::buffer(bytes), ec);
  }
  template <class Message>
  void send_message(const Message& message) {
    std::vector<std::uint8_t> bytes;
    codec::write_message(message, bytes);
    send(bytes);
  }
  void hello(const std::string& room, const std::string& name, const std::string& token = "",
             std::uint32_t max_bps = 0, bool timestamps = false) {
    codec::Hello h;
    h.room = room;
    h.name = name;
    h.token = token;
    h.max_bps = max_bps;
    h.timestamps = timestamps;
    send_message(h);
  }

  /// The next message, or nullopt after `timeout` or when the connection closed.
  std::optional<std::vector<std::uint8_t>> receive(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      if (closed_) return std::nullopt;
      if (transport_ == Transport::tcp) {
        std::span<const std::uint8_t> message;
        const auto status = deframer_.next(message);
        if (status == codec::TcpDeframer::Status::message)
          return std::vector<std::uint8_t>(message.begin(), message.end());
        if (status == codec::TcpDeframer::Status::error) {
          errors.push_back("bad length prefix from the server");
          closed_ = true;
          return std::nullopt;
        }
      }
      if (!reading_) start_read();
      ioc_.restart();
      while (!read_done_ && std::chrono::steady_clock::now() < deadline)
        ioc_.run_one_for(deadline - std::chrono::steady_clock::now());
      if (!read_done_) return std::nullopt;
      read_done_ = false;
      reading_ = false;
      if (read_error_) {
        closed_ = true;
        return std::nullopt;
      }
      if (transport_ == Transport::websocket) {
        const auto data = ws_buffer_.cdata();
        const auto* begin = static_cast<const std::uint8_t*>(data.data());
        std::vector<std::uint8_t> message(begin, begin + data.size());
        ws_buffer_.consume(ws_buffer_.size());
        return message;
      }
      deframer_.feed({tcp_buffer_.data(), tcp_bytes_});
      socket_bytes += tcp_bytes_;
    }
  }

  /// Reads and files messages until `done()` holds or `timeout` passes.
  template <class Predicate>
  bool pump_until(Predicate done, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      const auto now = std::chrono::steady_clock::now();
      if (now >= deadline || closed_) return done();
      auto message = receive(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now));
      if (message) file(*message);
    }
    return true;
  }
  void pump_for(std::chrono::milliseconds duration) {
    pump_until([] { return false; }, duration);
  }

  std::uint64_t socket_bytes = 0;  ///< TCP: everything read, length prefixes included
  bool closed() const { return closed_; }
  bool send_failed() const { return send_failed_; }
  /// The WebSocket close code (0 if none, or TCP).
  int websocket_close_code() const {
    return transport_ == Transport::websocket ? static_cast<int>(ws_.reason().code) : 0;
  }

 private:
  void start_read() {
    reading_ = true;
    read_done_ = false;
    read_error_ = false;
    if (transport_ == Transport::websocket) {
      ws_.async_read(ws_buffer_, [this](boost::system::error_code ec, std::size_t) {
        read_done_ = true;
        read_error_ = static_cast<bool>(ec);
      });
    } else {
      socket_.async_read_some(boost::asio::buffer(tcp_buffer_), [this](boost::system::error_code ec, std::size_t n) {
        read_done_ = true;
        read_error_ = static_cast<bool>(ec);
        tcp_bytes_ = n;
      });
    }
  }

  Transport transport_;
  boost::asio::io_context ioc_;
  boost::asio::ip::tcp::socket socket_;
  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::beast::flat_buffer ws_buffer_;
  std::array<std::uint8_t, 16384> tcp_buffer_{};
  std::size_t tcp_bytes_ = 0;
  codec::TcpDeframer deframer_{codec::kMaxDownstreamMessageBytes};
  bool connected_ = false, reading_ = false, read_done_ = false, read_error_ = false, closed_ = false;
  bool send_failed_ = false;
};

}  // namespace fw::test
