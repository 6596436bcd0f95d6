#include "tcp_session.hpp"

#include <array>

#include <boost/asio/write.hpp>

#include "server_limits.hpp"
#include "socket_queue.hpp"

namespace fw::server {

namespace net = boost::asio;
using codec::CloseCode;

TcpSession::TcpSession(const SessionServices& services, net::ip::tcp::socket&& socket, std::string peer,
                       ConnectionTicket ticket)
    : ClientSession(services, socket.get_executor(), std::move(peer)), ticket_(std::move(ticket)),
      socket_(std::move(socket)), linger_(executor_) {}

std::size_t TcpSession::framing_bytes(std::size_t message_bytes) const {
  return message_bytes < 128 ? 1 : message_bytes < 16384 ? 2 : 3;
}

void TcpSession::run() {
  // Until its hello the connection may give its place up to a newcomer
  // when the port is full (ConnectionShares).
  ticket_.waiting(std::chrono::steady_clock::now() + services_.config.timeouts.handshake);
  ticket_.on_evict([weak = weak_from_this()] {
    if (auto session = weak.lock()) session->give_up_place();
  });
  net::post(executor_, [self = std::static_pointer_cast<TcpSession>(shared_from_this())] {
    boost::system::error_code ignored;
    self->socket_.set_option(net::ip::tcp::no_delay(true), ignored);
    // A small kernel buffer keeps what waits for a slow peer in our queue,
    // where the room sees it and skips ticks, instead of in seconds of
    // stale frames inside the kernel.
    self->socket_.set_option(net::socket_base::send_buffer_size(limits::kSocketSendBufferBytes), ignored);
    self->start();
  });
}

void TcpSession::on_first_message() { ticket_.busy(); }

std::optional<SocketQueue> TcpSession::socket_queue() { return fw::server::socket_queue(socket_.native_handle()); }

void TcpSession::start_reading() {
  socket_.async_read_some(net::buffer(read_buffer_),
                          [self = std::static_pointer_cast<TcpSession>(shared_from_this())](
                              boost::system::error_code ec, std::size_t bytes) { self->on_read(ec, bytes); });
}

void TcpSession::on_read(boost::system::error_code ec, std::size_t bytes) {
  if (ec) {
    boost::system::error_code ignored;
    socket_.close(ignored);
    linger_.cancel();
    return on_transport_closed();
  }
  note_received(bytes);
  if (!shut_) {
    deframer_.feed({read_buffer_.data(), bytes});
    std::span<const std::uint8_t> message;
    for (;;) {
      const auto status = deframer_.next(message);
      if (status == codec::TcpDeframer::Status::need_more) break;
      if (status == codec::TcpDeframer::Status::error) {
        const bool too_large = deframer_.error() == codec::MessageError::too_large;
        services_.abuse.note(Abuse::protocol_violation, peer_,
                            too_large ? "TCP: a message over 8 KiB" : "TCP: a malformed length prefix");
        on_transport_error(too_large ? CloseCode::message_too_large : CloseCode::protocol_error,
                           too_large ? "a message over 8 KiB" : "a malformed length prefix");
        break;
      }
      on_message(message);
    }
  }
  // A peer closed for what it did is not read any more (closing_quickly).
  if (closing_quickly()) return;
  start_reading();  // until the peer closes: its close after our closing message ends it
}

void TcpSession::start_write(const SharedBytes& message) {
  prefix_.clear();
  codec::write_length_prefix(message->size(), prefix_);
  const std::array<net::const_buffer, 2> buffers = {net::buffer(prefix_), net::buffer(*message)};
  net::async_write(socket_, buffers,
                   [self = std::static_pointer_cast<TcpSession>(shared_from_this()), message](
                       boost::system::error_code ec, std::size_t written) { self->on_write_done(!ec, written); });
}

void TcpSession::shutdown_transport(CloseCode, const std::string&, bool abort) {
  boost::system::error_code ignored;
  if (abort) {
    socket_.close(ignored);
    return on_transport_closed();
  }
  // Half-close so the closing message is read before the socket goes; the
  // peer's own close ends the read loop, or the linger timer does.
  shut_ = true;
  socket_.shutdown(net::ip::tcp::socket::shutdown_send, ignored);
  if (closing_quickly())
    linger_.expires_after(limits::kQuickCloseLinger);
  else
    linger_.expires_after(std::chrono::seconds(3));
  linger_.async_wait([self = std::static_pointer_cast<TcpSession>(shared_from_this())](boost::system::error_code ec) {
    if (ec) return;
    boost::system::error_code ignored_too;
    self->socket_.close(ignored_too);
    self->on_transport_closed();  // no read may be waiting to say so
  });
}

}  // namespace fw::server
