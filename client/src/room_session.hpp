#pragma once
// The client's side of the room protocol (server/PROTOCOL.md): connects,
// says hello, decodes the stream into the RoomState, assembles packages,
// answers the codec's need for key frames, measures the clock offset to the
// server with pings, and reconnects with back-off when the connection
// drops. Everything runs on one io_context thread. The connections come
// from a TransportFactory: sockets in facewire-client
// (socket_transport.hpp), memory in the tests (in_memory_transport.hpp).
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "message_transport.hpp"
#include "package_assembler.hpp"
#include "room_state.hpp"
#include "server_clock.hpp"

namespace fw::client {

struct SessionOptions {
  std::string room;
  std::string name;
  std::string avatar_asset;  ///< empty: the server makes a procedural face
  std::string avatar_key;    ///< the key the upload of avatar_asset answered
  /// The package behind avatar_asset when the client uploaded it itself: the
  /// server is asked not to send it back, and the own face uses it at once.
  std::shared_ptr<const std::vector<std::uint8_t>> own_package;
  std::string token;
  std::uint32_t max_bps = 0;  ///< 0: the server's default
  bool timestamps = true;     ///< ask for timed room frames (latency measurements)
  std::vector<std::string> say;    ///< chat lines sent after the first welcome
  std::string emote;               ///< an emotion expressed after the first welcome
  /// Called on the session's thread for what a person should see at once
  /// (chat lines, arrivals, departures, refused commands, reconnects).
  std::function<void(const std::string&)> on_event;
};

class RoomSession {
 public:
  /// `transports` makes the connection of every attempt (the first, and
  /// each reconnection); `state` must outlive the session.
  RoomSession(boost::asio::io_context& io, SessionOptions options, RoomState& state, TransportFactory transports);
  ~RoomSession();
  RoomSession(const RoomSession&) = delete;
  RoomSession& operator=(const RoomSession&) = delete;

  void start();
  /// Closes the connection and stops reconnecting (call on the io thread,
  /// e.g. through asio::post).
  void stop();
  /// Sends a chat line (from the io thread).
  void chat(const std::string& text);
  /// Asks for a new downstream budget in bit/s (0: the server's default),
  /// now and in the hello of every later connection (from the io thread).
  void set_rate(std::uint32_t max_bps);

  /// Back-off between reconnection attempts: 0.5 s doubling to 8 s, back
  /// to 0.5 s after a welcome.
  static std::chrono::milliseconds backoff(int failed_attempts);

  static constexpr auto kHousekeepingInterval = std::chrono::milliseconds(250);
  static constexpr auto kPingInterval = std::chrono::seconds(2);
  static constexpr auto kResyncInterval = std::chrono::milliseconds(500);
  static constexpr std::size_t kMaxOutbox = 64;

 private:
  // A connection's life.
  void connect();
  void on_connected(boost::system::error_code ec);
  void start_over();
  void say_hello();
  void read();
  void connection_lost(const std::string& why);

  // What comes down.
  void on_message(std::span<const std::uint8_t> message);
  void on_stream_header(std::span<const std::uint8_t> message);
  void on_session_message(std::span<const std::uint8_t> message);
  codec::MessageError dispatch(codec::MessageType type, std::span<const std::uint8_t> message);
  template <class Message>
  codec::MessageError read_then(std::span<const std::uint8_t> bytes, void (RoomSession::*handle)(const Message&));
  void on_welcome(const codec::Welcome& welcome);
  void greet_once();
  void on_presence(const codec::Presence& presence);
  void on_chat(const codec::Chat& chat);
  void on_seats(const codec::Seats& seats);
  void on_attention(const codec::Attention& attention);
  void on_command_result(const codec::CommandResult& result);
  void on_package_chunk(const codec::PackageChunk& chunk);
  void on_pong(const codec::Pong& pong);
  void on_link_stats(const codec::LinkStats& link);
  void on_closing(const codec::Closing& closing);
  void on_timed_room_frame(const codec::TimedRoomFrame& timed);
  void on_room_frame(std::span<const std::uint8_t> room_frame, const codec::TimedRoomFrame* timing);

  // What goes up.
  template <class Message>
  void send_message(const Message& message);
  void send(std::vector<std::uint8_t> message);
  void write_next();
  void schedule_housekeeping();
  void housekeeping();
  void ping_when_due(std::chrono::steady_clock::time_point now);
  void request_key_frames_when_due(std::chrono::steady_clock::time_point now, std::vector<std::uint32_t> avatars);

  void event(const std::string& text);
  std::uint64_t now_us() const;

  boost::asio::io_context& io_;
  SessionOptions options_;
  RoomState& state_;
  TransportFactory transports_;
  std::shared_ptr<MessageTransport> transport_;
  boost::asio::steady_timer reconnect_timer_, housekeeping_timer_;
  PackageAssembler packages_;
  ServerClock server_clock_;
  std::deque<std::shared_ptr<const std::vector<std::uint8_t>>> outbox_;
  bool writing_ = false;
  bool stopped_ = false;
  bool greeted_ = false;  ///< the --say/--emote of the first welcome went out
  std::string resume_key_;  ///< the last welcome's, for the next hello after a drop
  int failed_attempts_ = 0;
  std::uint64_t connection_serial_ = 0;  ///< handlers of an old connection see a newer serial and stop
  std::uint32_t ping_nonce_ = 0;
  std::chrono::steady_clock::time_point last_ping_{}, last_resync_{};
  std::uint32_t command_serial_ = 0;

  static constexpr int kConnectTimeoutS = 10;
};

}  // namespace fw::client
