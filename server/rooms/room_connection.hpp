#pragma once
// How a room sees one subscriber's connection: it hands over whole messages
// and reads how much is still waiting, so that it can skip ticks instead of
// queueing (latest-value-wins). Thread-safe: the room calls from its strand.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fw/codec/messages.hpp"
#include "shared_bytes.hpp"

namespace fw::server {

class RoomConnection {
 public:
  virtual ~RoomConnection() = default;
  /// Queues one message for the socket.
  virtual void deliver(SharedBytes message) = 0;
  /// Bytes handed to deliver() and not yet written to the socket.
  virtual std::size_t queued_bytes() const = 0;
  /// Bytes written to the socket so far, framing included.
  virtual std::uint64_t bytes_written() const = 0;
  /// Per-message bytes the transport adds (length prefix, WebSocket header).
  virtual std::size_t framing_bytes(std::size_t message_bytes) const = 0;
  /// Sends a closing message, then closes.
  virtual void close(codec::CloseCode code, std::string reason) = 0;
  /// The room accepted this connection's hello: queues the welcome, then
  /// serves what the peer sent while it waited. One call, so that nothing
  /// the peer sends after reading the welcome can count as sent before it.
  virtual void joined(std::uint32_t avatar, SharedBytes welcome) = 0;
};

template <class Message>
SharedBytes encode_shared(const Message& message) {
  std::vector<std::uint8_t> bytes;
  codec::write_message(message, bytes);
  return share(std::move(bytes));
}

}  // namespace fw::server
