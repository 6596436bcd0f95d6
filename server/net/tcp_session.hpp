#pragma once
// A room connection over plain TCP: every message preceded by its length
// (PROTOCOL.md, "Framing on TCP"), for native clients. It keeps the
// connection's ticket (counted from accept to close).
#include <array>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "client_session.hpp"
#include "connection_admission.hpp"
#include "fw/codec/messages.hpp"

namespace fw::server {

class TcpSession : public ClientSession {
 public:
  TcpSession(const SessionServices& services, boost::asio::ip::tcp::socket&& socket, std::string peer,
             ConnectionTicket ticket);
  void run();
  std::size_t framing_bytes(std::size_t message_bytes) const override;

 private:
  void on_first_message() override;
  std::optional<SocketQueue> socket_queue() override;
  void start_reading() override;
  void start_write(const SharedBytes& message) override;
  void shutdown_transport(codec::CloseCode code, const std::string& reason, bool abort) override;
  void on_read(boost::system::error_code ec, std::size_t bytes);

  ConnectionTicket ticket_;
  boost::asio::ip::tcp::socket socket_;
  boost::asio::steady_timer linger_;
  std::array<std::uint8_t, 4096> read_buffer_{};
  std::vector<std::uint8_t> prefix_;
  codec::TcpDeframer deframer_{codec::kMaxUpstreamMessageBytes};
  bool shut_ = false;
};

}  // namespace fw::server
