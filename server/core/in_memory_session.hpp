#pragma once
// A room connection whose transport is a pipe in memory, beside
// WebSocketSession and TcpSession: the same ClientSession (hello checks,
// limits, time-outs, the bounded send queue), with a peer that is a program
// in the same process instead of a socket. Tests and benchmarks drive a room
// with it, with no port and no kernel buffer in between.
//
// The peer pushes whole upstream messages and takes what the server wrote.
// It can stop reading: the write in progress then never completes, as on a
// socket whose peer does not read, so what the room delivers stays queued
// and queued_bytes() grows until the room skips ticks (latest value wins).
//
// Thread-safe: the peer's calls may come from any thread; the session itself
// runs on its executor (give it a strand of its own, as the listeners do).
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

#include "client_session.hpp"

namespace fw::server {

class InMemorySession : public ClientSession {
 public:
  InMemorySession(const SessionServices& services, boost::asio::any_io_executor executor,
                  std::string peer = "in-memory");

  /// The peer is connected: the session starts its clock and takes messages.
  void run();
  /// The peer sends one whole upstream message.
  void push(std::vector<std::uint8_t> message);
  template <class Message>
  void push_message(const Message& message) {
    std::vector<std::uint8_t> bytes;
    codec::write_message(message, bytes);
    push(std::move(bytes));
  }
  /// The peer closes its end (a TCP FIN, a WebSocket close).
  void hang_up();
  /// false: the peer stops reading; the write in progress stays unfinished.
  /// true: it reads again, and everything waiting is written.
  void set_reading(bool reading);

  /// Messages written to the peer since the last call, in order (moved out).
  std::vector<SharedBytes> take_written();
  /// The server ended the transport: after its closing message (nullopt
  /// while it has not), or at once (aborted(): it would not wait for a peer
  /// that does not read).
  std::optional<codec::CloseCode> shut_down() const;
  bool aborted() const;
  /// The session has let go of its room and its registry entry.
  bool gone() const;

  /// As TcpSession's length prefix, so that budgets count what a TCP link carries.
  std::size_t framing_bytes(std::size_t message_bytes) const override;

 private:
  void start_reading() override;
  void start_write(const SharedBytes& message) override;
  void shutdown_transport(codec::CloseCode code, const std::string& reason, bool abort) override;
  void complete_write();
  void fail_pending_write();
  std::shared_ptr<InMemorySession> self();

  // On the executor.
  SharedBytes pending_;  ///< the write in progress, unfinished while the peer does not read
  bool reading_ = true;

  // Shared with the peer's thread.
  mutable std::mutex mutex_;
  std::deque<SharedBytes> written_;
  std::optional<codec::CloseCode> shut_down_;
  bool aborted_ = false;
  bool gone_ = false;
};

}  // namespace fw::server
