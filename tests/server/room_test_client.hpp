#pragma once
// A room-protocol client for the server tests: WebSocket or length-prefixed
// TCP, synchronous calls with time-outs (an io_context run for a while), and
// the bookkeeping the tests check: welcome, presence, chat, closing, room
// frames decoded by a codec::RoomDecoder, package chunks reassembled.
#include <chrono>
#include <map>
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

namespace fw::test {

class RoomTestClient {
 public:
  enum class Transport { websocket, tcp };

  RoomTestClient(Transport transport, int port) : transport_(transport), socket_(ioc_), ws_(ioc_) {
    namespace net = boost::asio;
    const net::ip::tcp::endpoint endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port));
    boost::system::error_code ec;
    if (transport_ == Transport::websocket) {
      boost::beast::get_lowest_layer(ws_).connect(endpoint, ec);
      if (!ec) {
        ws_.binary(true);
        ws_.handshake("127.0.0.1", "/ws", ec);
      }
    } else {
      socket_.connect(endpoint, ec);
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

  // What arrived so far.
  std::optional<codec::Welcome> welcome;
  std::optional<codec::Closing> closing;
  std::optional<codec::LinkStats> link;  ///< the latest
  bool stream_header = false;
  std::vector<codec::Presence> presence;
  std::vector<codec::Chat> chat;
  std::vector<codec::CommandResult> results;
  std::uint64_t room_frames = 0;
  std::uint64_t bytes_received = 0;
  std::uint64_t socket_bytes = 0;      ///< TCP: everything read, length prefixes included
  std::uint64_t room_frame_bytes = 0;  ///< of the codec room frames (timestamps excluded)
  std::uint64_t package_bytes = 0;     ///< of package chunk messages
  std::map<std::uint32_t, std::uint64_t> frames_per_avatar;
  std::vector<std::string> errors;  ///< anything a correct server never sends
  /// Timed room frames: when each arrived and its tick.
  std::vector<std::pair<std::chrono::steady_clock::time_point, std::uint32_t>> ticks;
  /// Arrival minus the server's tick time (same host, same monotonic clock).
  std::vector<std::int64_t> latency_us;
  static std::int64_t now_us() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  struct Package {
    std::vector<std::uint8_t> bytes;
    std::size_t received = 0;
    bool complete() const { return !bytes.empty() && received == bytes.size(); }
  };
  std::map<std::pair<std::uint32_t, int>, Package> packages;  ///< (avatar, quality)
  std::vector<std::pair<std::uint32_t, int>> package_order;   ///< as completed
  codec::RoomDecoder decoder;
  bool closed() const { return closed_; }
  bool send_failed() const { return send_failed_; }
  /// The WebSocket close code (0 if none, or TCP).
  int websocket_close_code() const {
    return transport_ == Transport::websocket ? static_cast<int>(ws_.reason().code) : 0;
  }

  void file(const std::vector<std::uint8_t>& m) {
    bytes_received += m.size();
    switch (codec::classify(m)) {
      case codec::MessageKind::stream_header: stream_header = true; return;
      case codec::MessageKind::room_frame: return file_room_frame(m);
      case codec::MessageKind::session: break;
      default: errors.push_back("unexpected first byte " + std::to_string(m.empty() ? -1 : m[0])); return;
    }
    const auto check = [&](codec::MessageError e, const char* what) {
      if (e != codec::MessageError::ok) errors.push_back(std::string(what) + ": " + std::string(codec::describe(e)));
      return e == codec::MessageError::ok;
    };
    switch (codec::session_type(m)) {
      case codec::MessageType::welcome: {
        codec::Welcome w;
        if (check(codec::read_message(m, w), "welcome")) welcome = w;
        return;
      }
      case codec::MessageType::presence: {
        codec::Presence p;
        if (check(codec::read_message(m, p), "presence")) {
          if (p.change == codec::Presence::Change::left) decoder.remove(p.avatar.id);
          presence.push_back(p);
        }
        return;
      }
      case codec::MessageType::chat: {
        codec::Chat c;
        if (check(codec::read_message(m, c), "chat")) chat.push_back(c);
        return;
      }
      case codec::MessageType::command_result: {
        codec::CommandResult r;
        if (check(codec::read_message(m, r), "command result")) results.push_back(r);
        return;
      }
      case codec::MessageType::closing: {
        codec::Closing c;
        if (check(codec::read_message(m, c), "closing")) closing = c;
        return;
      }
      case codec::MessageType::timed_room_frame: {
        codec::TimedRoomFrame t;
        if (check(codec::read_message(m, t), "timed room frame")) {
          ticks.emplace_back(std::chrono::steady_clock::now(), t.tick);
          latency_us.push_back(now_us() - static_cast<std::int64_t>(t.server_time_us));
        }
        if (!errors.empty()) return;
        file_room_frame(std::vector<std::uint8_t>(t.room_frame.begin(), t.room_frame.end()));
        return;
      }
      case codec::MessageType::package_chunk: {
        codec::PackageChunk c;
        package_bytes += m.size();
        if (!check(codec::read_message(m, c), "package chunk")) return;
        auto& p = packages[{c.avatar, static_cast<int>(c.quality)}];
        if (p.bytes.empty()) p.bytes.resize(c.total_bytes);
        if (p.bytes.size() != c.total_bytes || c.offset != p.received) {
          errors.push_back("package chunk out of order");
          return;
        }
        std::copy(c.data.begin(), c.data.end(), p.bytes.begin() + c.offset);
        p.received += c.data.size();
        if (p.complete()) package_order.emplace_back(c.avatar, static_cast<int>(c.quality));
        return;
      }
      case codec::MessageType::link_stats: {
        codec::LinkStats l;
        if (check(codec::read_message(m, l), "link statistics")) link = l;
        return;
      }
      case codec::MessageType::pong: return;
      default: errors.push_back("a message the server never sends"); return;
    }
  }

 private:
  void file_room_frame(const std::vector<std::uint8_t>& m) {
    ++room_frames;
    room_frame_bytes += m.size();
    const auto result = decoder.decode(m);
    if (result.error != codec::DecodeError::ok) {
      errors.push_back("room frame: " + std::string(codec::describe(result.error)));
      return;
    }
    for (const auto& [id, error] : result.avatars) {
      if (error != codec::DecodeError::ok) errors.push_back("avatar frame: " + std::string(codec::describe(error)));
      ++frames_per_avatar[id];
    }
  }

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
