#include "room_test_client.hpp"

#include <array>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include "fw/codec/codec.hpp"

namespace fw::test {

struct RoomTestClient::Connection {
  explicit Connection(Transport t) : transport(t), socket(ioc), ws(ioc) {}

  boost::asio::ip::tcp::socket& lowest_socket() {
    return transport == Transport::tcp ? socket : boost::beast::get_lowest_layer(ws).socket();
  }

  void start_read() {
    reading = true;
    read_done = false;
    read_error = false;
    if (transport == Transport::websocket) {
      ws.async_read(ws_buffer, [this](boost::system::error_code ec, std::size_t) {
        read_done = true;
        read_error = static_cast<bool>(ec);
      });
    } else {
      socket.async_read_some(boost::asio::buffer(tcp_buffer), [this](boost::system::error_code ec, std::size_t n) {
        read_done = true;
        read_error = static_cast<bool>(ec);
        tcp_bytes = n;
      });
    }
  }

  Transport transport;
  boost::asio::io_context ioc;
  boost::asio::ip::tcp::socket socket;
  boost::beast::websocket::stream<boost::beast::tcp_stream> ws;
  boost::beast::flat_buffer ws_buffer;
  std::array<std::uint8_t, 16384> tcp_buffer{};
  std::size_t tcp_bytes = 0;
  codec::TcpDeframer deframer{codec::kMaxDownstreamMessageBytes};
  bool connected = false, reading = false, read_done = false, read_error = false, closed = false;
  bool send_failed = false;
};

RoomTestClient::RoomTestClient(Transport transport, int port, const std::string& from, const std::string& x_forwarded_for)
    : connection_(std::make_unique<Connection>(transport)) {
  namespace net = boost::asio;
  Connection& c = *connection_;
  const net::ip::tcp::endpoint endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port));
  boost::system::error_code ec;
  auto& socket = c.lowest_socket();
  if (!from.empty()) {
    socket.open(net::ip::tcp::v4(), ec);
    if (!ec) socket.bind({net::ip::make_address(from), 0}, ec);
  }
  if (!ec) socket.connect(endpoint, ec);
  if (!ec && transport == Transport::websocket) {
    c.ws.binary(true);
    if (!x_forwarded_for.empty())
      c.ws.set_option(boost::beast::websocket::stream_base::decorator(
          [x_forwarded_for](boost::beast::websocket::request_type& request) {
            request.set("X-Forwarded-For", x_forwarded_for);
          }));
    c.ws.handshake("127.0.0.1", "/ws", ec);
  }
  c.connected = !ec;
}

RoomTestClient::~RoomTestClient() = default;

bool RoomTestClient::connected() const { return connection_->connected; }
bool RoomTestClient::closed() const { return connection_->closed; }
bool RoomTestClient::send_failed() const { return connection_->send_failed; }

int RoomTestClient::websocket_close_code() const {
  return connection_->transport == Transport::websocket ? static_cast<int>(connection_->ws.reason().code) : 0;
}

void RoomTestClient::shrink_receive_buffer(int bytes) {
  boost::system::error_code ec;
  connection_->lowest_socket().set_option(boost::asio::socket_base::receive_buffer_size(bytes), ec);
}

void RoomTestClient::send(const std::vector<std::uint8_t>& message) {
  Connection& c = *connection_;
  boost::system::error_code ec;
  if (c.transport == Transport::websocket) {
    c.ws.write(boost::asio::buffer(message), ec);
  } else {
    std::vector<std::uint8_t> framed;
    codec::write_tcp_frame(message, framed);
    boost::asio::write(c.socket, boost::asio::buffer(framed), ec);
  }
  if (ec) c.send_failed = true;
}

void RoomTestClient::send_raw(const std::vector<std::uint8_t>& bytes) {
  boost::system::error_code ec;
  boost::asio::write(connection_->socket, boost::asio::buffer(bytes), ec);
}

void RoomTestClient::hello(const std::string& room, const std::string& name, const std::string& token,
                           std::uint32_t max_bps, bool timestamps) {
  codec::Hello h;
  h.room = room;
  h.name = name;
  h.token = token;
  h.max_bps = max_bps;
  h.timestamps = timestamps;
  send_message(h);
}

std::optional<std::vector<std::uint8_t>> RoomTestClient::receive(std::chrono::milliseconds timeout) {
  Connection& c = *connection_;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (c.closed) return std::nullopt;
    if (c.transport == Transport::tcp) {
      std::span<const std::uint8_t> message;
      const auto status = c.deframer.next(message);
      if (status == codec::TcpDeframer::Status::message) return std::vector<std::uint8_t>(message.begin(), message.end());
      if (status == codec::TcpDeframer::Status::error) {
        errors.push_back("bad length prefix from the server");
        c.closed = true;
        return std::nullopt;
      }
    }
    if (!c.reading) c.start_read();
    c.ioc.restart();
    while (!c.read_done && std::chrono::steady_clock::now() < deadline)
      c.ioc.run_one_for(deadline - std::chrono::steady_clock::now());
    if (!c.read_done) return std::nullopt;
    c.read_done = false;
    c.reading = false;
    if (c.read_error) {
      c.closed = true;
      return std::nullopt;
    }
    if (c.transport == Transport::websocket) {
      const auto data = c.ws_buffer.cdata();
      const auto* begin = static_cast<const std::uint8_t*>(data.data());
      std::vector<std::uint8_t> message(begin, begin + data.size());
      c.ws_buffer.consume(c.ws_buffer.size());
      return message;
    }
    c.deframer.feed({c.tcp_buffer.data(), c.tcp_bytes});
    socket_bytes += c.tcp_bytes;
  }
}

}  // namespace fw::test
