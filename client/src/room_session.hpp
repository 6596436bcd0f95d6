#pragma once
// The client's side of the room protocol (server/PROTOCOL.md): connects,
// says hello, decodes the stream into the RoomState, assembles packages,
// answers the codec's need for key frames, measures the clock offset to the
// server with pings, and reconnects with back-off when the connection
// drops. Everything runs on one io_context thread.
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "message_channel.hpp"
#include "package_assembler.hpp"
#include "room_state.hpp"
#include "server_url.hpp"

namespace fw::client {

struct SessionOptions {
  ServerUrl url;
  std::string room;
  std::string name;
  std::string avatar_asset;  ///< empty: the server makes a procedural face
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
  RoomSession(boost::asio::io_context& io, SessionOptions options, RoomState& state);
  ~RoomSession();
  RoomSession(const RoomSession&) = delete;
  RoomSession& operator=(const RoomSession&) = delete;

  void start();
  /// Closes the connection and stops reconnecting (call on the io thread,
  /// e.g. through asio::post).
  void stop();
  /// Sends a chat line (from the io thread).
  void chat(const std::string& text);

  /// Back-off between reconnection attempts: 0.5 s doubling to 8 s, back
  /// to 0.5 s after a welcome.
  static std::chrono::milliseconds backoff(int failed_attempts);

 private:
  void connect();
  void on_connected(boost::system::error_code ec);
  void read();
  void on_message(std::span<const std::uint8_t> message);
  void on_session_message(std::span<const std::uint8_t> message);
  void on_room_frame(std::span<const std::uint8_t> room_frame, const codec::TimedRoomFrame* timing);
  void on_welcome(const codec::Welcome& welcome);
  void on_closing(const codec::Closing& closing);
  void send(std::vector<std::uint8_t> message);
  void write_next();
  void tick_timers();
  void connection_lost(const std::string& why);
  void event(const std::string& text);
  std::uint64_t now_us() const;

  boost::asio::io_context& io_;
  SessionOptions options_;
  RoomState& state_;
  std::shared_ptr<MessageChannel> channel_;
  boost::asio::steady_timer reconnect_timer_, housekeeping_timer_;
  PackageAssembler packages_;
  std::deque<std::shared_ptr<const std::vector<std::uint8_t>>> outbox_;
  bool writing_ = false;
  bool stopped_ = false;
  bool greeted_ = false;  ///< the --say/--emote of the first welcome went out
  int failed_attempts_ = 0;
  std::uint64_t connection_serial_ = 0;  ///< handlers of an old connection see a newer serial and stop
  // Clock offset (server minus client, microseconds) from the ping with the
  // shortest round trip seen on this connection.
  std::optional<std::int64_t> clock_offset_us_;
  std::uint64_t best_round_trip_us_ = UINT64_MAX;
  std::uint32_t ping_nonce_ = 0;
  std::chrono::steady_clock::time_point last_ping_{}, last_resync_{};
  std::uint32_t command_serial_ = 0;

  static constexpr std::size_t kMaxOutbox = 64;
  static constexpr int kConnectTimeoutS = 10;
};

}  // namespace fw::client
