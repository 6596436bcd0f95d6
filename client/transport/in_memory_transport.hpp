#pragma once
// Connections that never leave the process: the session's end is a
// MessageTransport, the far end an InMemoryServerEnd that code in the same
// process drives. The session's tests play the server through it: they push
// the server's messages down, read what the session sent up, drop
// connections and refuse new ones, all without a socket or a thread.
//
// Single-threaded, like the sockets it stands in for: use both ends from
// the io_context's thread. Completions are posted to the io_context (never
// run inside the call that started them), so the session sees the same
// order of events as on a socket; run the io_context to deliver them.
#include <cstdint>
#include <memory>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/system/error_code.hpp>

#include "message_transport.hpp"

namespace fw::client {

class InMemoryConnection;

/// The server's side of in-memory connections. Always talks to the newest
/// connection: older ones were dropped or closed by the session.
class InMemoryServerEnd {
 public:
  explicit InMemoryServerEnd(boost::asio::io_context& io);

  /// For RoomSession: each call makes the transport of the next connection.
  /// The factory refers to this object, which must outlive its transports.
  TransportFactory transports();

  /// Connections made from now on fail to connect with `error` (a server
  /// that is down); a default error_code accepts them again.
  void refuse_connections(boost::system::error_code error) { refusal_ = error; }

  /// Sends one message down the newest connection (ignored when it ended).
  void send(std::vector<std::uint8_t> message);
  /// The server closes the newest connection: messages already sent are
  /// still read, then reads end with end of file and writes fail.
  void drop();
  /// The messages the session wrote on the newest connection since the
  /// last call, oldest first (taken out).
  std::vector<std::vector<std::uint8_t>> take_received();

  /// How many transports the session asked for (connection attempts).
  int attempts() const { return attempts_; }
  /// Whether the newest connection is connected and neither end closed it.
  bool connected() const;
  /// Whether the session closed the newest connection itself.
  bool closed_by_client() const;

 private:
  boost::asio::io_context& io_;
  boost::system::error_code refusal_;
  std::shared_ptr<InMemoryConnection> newest_;
  int attempts_ = 0;
};

}  // namespace fw::client
