#pragma once
// A room connection over WebSocket: one protocol message per binary
// WebSocket message (PROTOCOL.md, "Transports"). Created by HttpSession
// when a request asks for the upgrade; it keeps the connection's ticket
// (counted from accept to close). Pings and pongs count as messages in the
// session's rate limits.
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "client_session.hpp"
#include "connection_admission.hpp"

namespace fw::server {

class WebSocketSession : public ClientSession {
 public:
  WebSocketSession(const SessionServices& services, boost::beast::tcp_stream&& stream, std::string peer,
                   ConnectionTicket ticket);
  /// Answers the upgrade request, then runs the protocol.
  void run(boost::beast::http::request<boost::beast::http::string_body> request);
  std::size_t framing_bytes(std::size_t message_bytes) const override;

 private:
  void on_first_message() override;
  std::optional<SocketQueue> socket_queue() override;
  void start_reading() override;
  void start_write(const SharedBytes& message) override;
  void shutdown_transport(codec::CloseCode code, const std::string& reason, bool abort) override;
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  /// Counts (AbuseLog) a read that ended in a WebSocket protocol violation.
  void note_violation(const boost::beast::error_code& ec);

  ConnectionTicket ticket_;
  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::beast::flat_buffer buffer_;
  boost::asio::steady_timer linger_;  ///< a quick close's half-closed wait (closing_quickly)
};

}  // namespace fw::server
