#pragma once
// One connection to the room server that carries whole binary messages, as
// the session sees it. The session (room_session.hpp) speaks the protocol;
// a transport only moves messages. Two kinds exist: the sockets of
// socket_transport.hpp (WebSocket, or TCP with the protocol's length
// prefix), and in_memory_transport.hpp, whose far end is code in the same
// process (the session's tests play the server through it).
//
// Not thread-safe: use a transport from its io_context's thread. One read
// and one write may be outstanding at a time. Completion handlers run from
// the io_context, or (reads of a message that is already buffered) at once.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <boost/system/error_code.hpp>

namespace fw::client {

class MessageTransport : public std::enable_shared_from_this<MessageTransport> {
 public:
  using Done = std::function<void(boost::system::error_code)>;
  /// `message` is valid only during the call.
  using Received = std::function<void(boost::system::error_code, std::span<const std::uint8_t> message)>;

  virtual ~MessageTransport() = default;

  /// Resolves, connects and (WebSocket) upgrades, within `timeout_s` seconds.
  virtual void connect(int timeout_s, Done done) = 0;
  /// Reads the next message (at most codec::kMaxDownstreamMessageBytes).
  virtual void read(Received received) = 0;
  /// Sends one message; `message` is kept alive until `done`.
  virtual void write(std::shared_ptr<const std::vector<std::uint8_t>> message, Done done) = 0;
  /// Closes at once; outstanding operations complete with an error.
  virtual void close() = 0;
  /// Bytes the transport adds to a message of `message_bytes` (the length
  /// prefix, or the WebSocket frame header): counted in the link statistics.
  virtual std::size_t framing_bytes(std::size_t message_bytes, bool upstream) const = 0;
};

/// Makes a fresh, unconnected transport for every connection attempt (the
/// session reconnects through it after a drop).
using TransportFactory = std::function<std::shared_ptr<MessageTransport>()>;

/// The same for a list of servers: a transport to the server of this index
/// (the session moves through the list when a link fails).
using ServerTransportFactory = std::function<std::shared_ptr<MessageTransport>(std::size_t server)>;

}  // namespace fw::client
