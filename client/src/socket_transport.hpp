#pragma once
// One connection to the room server that carries whole binary messages:
// WebSocket (Boost.Beast) or TCP with the protocol's length prefix
// (codec/messages.hpp, TcpDeframer). The session above speaks the protocol;
// this only moves messages. Not thread-safe: use it from the io_context's
// thread; one read and one write may be outstanding at a time.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/system/error_code.hpp>

#include "server_url.hpp"

namespace fw::client {

class MessageChannel : public std::enable_shared_from_this<MessageChannel> {
 public:
  using Done = std::function<void(boost::system::error_code)>;
  /// `message` is valid only during the call.
  using Received = std::function<void(boost::system::error_code, std::span<const std::uint8_t> message)>;

  /// A channel for `url`'s scheme (not yet connected).
  /// Handlers keep the channel alive until they ran.
  static std::shared_ptr<MessageChannel> make(boost::asio::io_context& io, const ServerUrl& url);
  virtual ~MessageChannel() = default;

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

}  // namespace fw::client
