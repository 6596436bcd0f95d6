#include "websocket_session.hpp"

#include <spdlog/spdlog.h>

#include "server_limits.hpp"
#include "socket_queue.hpp"

namespace fw::server {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
using codec::CloseCode;

namespace {

/// A client's control frame: two bytes of header and a four-byte mask.
constexpr std::size_t kControlFrameHeaderBytes = 6;

websocket::close_code close_code_for(CloseCode code) {
  switch (code) {
    case CloseCode::normal: return websocket::close_code::normal;
    case CloseCode::shutting_down: return websocket::close_code::going_away;
    case CloseCode::message_too_large: return websocket::close_code::too_big;
    case CloseCode::unauthorized:
    case CloseCode::rate_limited:
    case CloseCode::room_full:
    case CloseCode::server_full:
    case CloseCode::handshake_timeout:
    case CloseCode::idle_timeout: return websocket::close_code::policy_error;
    case CloseCode::avatar_being_prepared: return websocket::close_code::try_again_later;
    default: return websocket::close_code::protocol_error;
  }
}

}  // namespace

WebSocketSession::WebSocketSession(const SessionServices& services, beast::tcp_stream&& stream, std::string peer,
                                   ConnectionTicket ticket)
    : ClientSession(services, stream.get_executor(), std::move(peer)), ticket_(std::move(ticket)),
      ws_(std::move(stream)), linger_(ws_.get_executor()) {}

std::size_t WebSocketSession::framing_bytes(std::size_t message_bytes) const {
  return message_bytes < 126 ? 2 : message_bytes < 65536 ? 4 : 10;  // server frames are not masked
}

void WebSocketSession::run(beast::http::request<beast::http::string_body> request) {
  beast::get_lowest_layer(ws_).expires_never();  // the websocket's own time-outs from here on
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().set_option(
      boost::asio::socket_base::send_buffer_size(limits::kSocketSendBufferBytes), ignored);  // as TcpSession
  websocket::stream_base::timeout timeout{};
  timeout.handshake_timeout = services_.config.timeouts.handshake;
  timeout.idle_timeout = websocket::stream_base::none();  // the session's idle clock decides
  timeout.keep_alive_pings = false;
  ws_.set_option(timeout);
  ws_.read_message_max(codec::kMaxUpstreamMessageBytes);
  ws_.binary(true);
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& response) { response.set(beast::http::field::server, "facewire"); }));
  // Beast answers pings by itself: each ping (and pong) is counted as a
  // message, so that a flood of them is closed like any other. The stream
  // only calls this while a read is under way, which holds the session.
  ws_.control_callback([this](websocket::frame_type kind, beast::string_view payload) {
    if (kind == websocket::frame_type::close) return;
    note_received(payload.size() + kControlFrameHeaderBytes);
    note_control_frame(payload.size() + kControlFrameHeaderBytes);
  });
  auto self = std::static_pointer_cast<WebSocketSession>(shared_from_this());
  // Until its hello the connection may give its place up to a newcomer
  // when the port is full (ConnectionShares).
  ticket_.waiting(std::chrono::steady_clock::now() + services_.config.timeouts.handshake);
  ticket_.on_evict([weak = std::weak_ptr<WebSocketSession>(self)] {
    if (auto session = weak.lock()) session->give_up_place();
  });
  ws_.async_accept(request, [self](beast::error_code ec) {
    if (ec) {
      // Beast answered a bad upgrade request with 400 itself.
      if (ec != beast::error::timeout && ec != boost::asio::error::connection_reset && ec != boost::asio::error::eof &&
          ec != boost::asio::error::broken_pipe)
        self->services_.abuse.note(Abuse::http_bad_request, self->peer_, "400: WebSocket upgrade: " + ec.message());
      return;
    }
    self->start();
  });
}

void WebSocketSession::on_first_message() { ticket_.busy(); }

std::optional<SocketQueue> WebSocketSession::socket_queue() {
  return fw::server::socket_queue(beast::get_lowest_layer(ws_).socket().native_handle());
}

void WebSocketSession::start_reading() {
  ws_.async_read(buffer_, beast::bind_front_handler(&WebSocketSession::on_read,
                                                    std::static_pointer_cast<WebSocketSession>(shared_from_this())));
}

void WebSocketSession::on_read(beast::error_code ec, std::size_t bytes) {
  if (ec == websocket::error::message_too_big) {
    // Beast has answered with close code 1009 already; the closing message
    // cannot follow on a closed stream, so this only counts and logs it.
    services_.abuse.note(Abuse::protocol_violation, peer_, "a WebSocket message over 8 KiB");
    on_transport_error(CloseCode::message_too_large, "a message over 8 KiB");
    return on_transport_closed();
  }
  if (ec) {
    note_violation(ec);
    return on_transport_closed();
  }
  note_received(bytes);
  if (!ws_.got_binary()) {
    services_.abuse.note(Abuse::protocol_violation, peer_, "a WebSocket text message");
    on_transport_error(CloseCode::protocol_error, "a text message; the protocol sends binary messages only");
  } else {
    const auto data = buffer_.cdata();
    on_message({static_cast<const std::uint8_t*>(data.data()), data.size()});
  }
  buffer_.consume(buffer_.size());
  // A peer closed for what it did is not read any more (closing_quickly).
  if (closing_quickly()) return;
  start_reading();  // reading on lets the close handshake complete
}

void WebSocketSession::note_violation(const beast::error_code& ec) {
  // Beast's own WebSocket errors: bad frames, bad masking, bad UTF-8 in a
  // close... (its "closed" is the peer's orderly close, not a violation).
  if (ec.category() != websocket::make_error_code(websocket::error::closed).category()) return;
  if (ec == websocket::error::closed) return;
  services_.abuse.note(Abuse::protocol_violation, peer_, "WebSocket: " + ec.message());
}

void WebSocketSession::start_write(const SharedBytes& message) {
  auto self = std::static_pointer_cast<WebSocketSession>(shared_from_this());
  ws_.async_write(boost::asio::buffer(*message), [self, message](beast::error_code ec, std::size_t bytes) {
    self->on_write_done(!ec, bytes + self->framing_bytes(bytes));
  });
}

void WebSocketSession::shutdown_transport(CloseCode code, const std::string& reason, bool abort) {
  if (abort) {
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
    return on_transport_closed();
  }
  auto self = std::static_pointer_cast<WebSocketSession>(shared_from_this());
  if (closing_quickly()) {
    // No close handshake with a peer that floods or stays silent: it would
    // keep reading the flood, or wait the handshake time-out, for nothing.
    // The closing message went out; the FIN follows it.
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
    linger_.expires_after(limits::kQuickCloseLinger);
    linger_.async_wait([self](beast::error_code ec) {
      if (ec) return;
      beast::error_code ignored_too;
      beast::get_lowest_layer(self->ws_).socket().close(ignored_too);
      self->on_transport_closed();
    });
    return;
  }
  websocket::close_reason why(close_code_for(code), reason.substr(0, 120));
  ws_.async_close(why, [self](beast::error_code) { self->on_transport_closed(); });
}

}  // namespace fw::server
