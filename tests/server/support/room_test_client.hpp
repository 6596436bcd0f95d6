#pragma once
// A room-protocol client for the server tests: WebSocket or length-prefixed
// TCP, synchronous calls with time-outs (an io_context run for a while), and
// the bookkeeping the tests check (room_inbox.hpp). Its Beast and Asio code
// lives in room_test_client.cpp, compiled once into fw_server_test_support:
// instantiating Beast's WebSocket stream took 18 of the 19.5 s that each of
// the 13 test executables including this header spent compiling.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fw/codec/messages.hpp"
#include "room_inbox.hpp"

namespace fw::test {

class RoomTestClient : public RoomInbox {
 public:
  enum class Transport { websocket, tcp };

  /// `from`: the local address to connect from (127.0.0.2 and up stand in
  /// for other clients' addresses); empty: the kernel's choice, 127.0.0.1.
  /// `x_forwarded_for`: that header on the WebSocket upgrade (as a proxy
  /// would send it); empty: none.
  RoomTestClient(Transport transport, int port, const std::string& from = "", const std::string& x_forwarded_for = "");
  ~RoomTestClient();
  RoomTestClient(const RoomTestClient&) = delete;
  RoomTestClient& operator=(const RoomTestClient&) = delete;

  bool connected() const;
  /// Shrinks the kernel's receive buffer (before anything is read), so that
  /// a client that stops reading pushes back on the server quickly.
  void shrink_receive_buffer(int bytes);

  void send(const std::vector<std::uint8_t>& message);
  /// Bytes exactly as given (TCP: no prefix added).
  void send_raw(const std::vector<std::uint8_t>& bytes);
  template <class Message>
  void send_message(const Message& message) {
    std::vector<std::uint8_t> bytes;
    codec::write_message(message, bytes);
    send(bytes);
  }
  void hello(const std::string& room, const std::string& name, const std::string& token = "",
             std::uint32_t max_bps = 0, bool timestamps = false);

  /// The next message, or nullopt after `timeout` or when the connection closed.
  std::optional<std::vector<std::uint8_t>> receive(std::chrono::milliseconds timeout);

  /// Reads and files messages until `done()` holds or `timeout` passes.
  template <class Predicate>
  bool pump_until(Predicate done, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      const auto now = std::chrono::steady_clock::now();
      if (now >= deadline || closed()) return done();
      auto message = receive(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now));
      if (message) file(*message);
    }
    return true;
  }
  void pump_for(std::chrono::milliseconds duration) {
    pump_until([] { return false; }, duration);
  }

  std::uint64_t socket_bytes = 0;  ///< TCP: everything read, length prefixes included
  bool closed() const;
  bool send_failed() const;
  /// The WebSocket close code (0 if none, or TCP).
  int websocket_close_code() const;

 private:
  struct Connection;  // the sockets, buffers and read state (room_test_client.cpp)
  std::unique_ptr<Connection> connection_;
};

}  // namespace fw::test
