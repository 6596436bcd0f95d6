#pragma once
// The client's side of the room protocol (server/PROTOCOL.md): connects,
// says hello, decodes the stream into the RoomState, assembles packages,
// answers the codec's need for key frames, measures the clock offset to the
// server with pings, and reconnects with back-off when the connection
// drops, moving on to the next server when it was given several
// (failover_policy.hpp), and uploading the person's face again to a server
// that does not know it. Everything runs on one io_context thread. The
// connections come from a TransportFactory: sockets in facewire-client
// (socket_transport.hpp), memory in the tests (in_memory_transport.hpp).
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "failover_policy.hpp"
#include "message_transport.hpp"
#include "package_assembler.hpp"
#include "room_state.hpp"
#include "server_clock.hpp"

namespace fw::client {

/// What a hello names to wear an uploaded face on one server.
struct AvatarCredentials {
  std::string asset;  ///< the asset id
  std::string key;    ///< the key the upload answered
};

/// How an upload the session asked for went.
struct ReuploadResult {
  bool ok = false;
  AvatarCredentials credentials;  ///< when ok
  bool try_elsewhere = false;     ///< it failed, but another server may take it (no answer, 429, 5xx)
  std::string error;              ///< what went wrong, for the person
};
using ReuploadDone = std::function<void(ReuploadResult)>;
/// Uploads the person's face to the server of this index; `done` runs on
/// the session's io_context.
using AvatarReuploader = std::function<void(std::size_t server, ReuploadDone done)>;

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
  /// The language the person's lines are said in (hello version 4); empty:
  /// the server's default. Its shape is checked before (join_arguments).
  std::string language;
  /// Called on the session's thread for what a person should see at once
  /// (chat lines, arrivals, departures, refused commands, reconnects).
  std::function<void(const std::string&)> on_event;
  /// The servers' URLs as the person wrote them, for what they read (to
  /// which server the session moved, and why); the transport factory is
  /// given their index. Empty: one server.
  std::vector<std::string> servers;
  std::size_t first_server = 0;  ///< where the first connection goes: where the face was uploaded
  /// Uploads the face again, to a server that does not know it (another
  /// node that does not share the first one's avatars). Empty when the
  /// person brings no face of their own.
  AvatarReuploader reupload;
};

class RoomSession {
 public:
  /// `transports` makes the connection of every attempt (the first, and
  /// each reconnection); `state` must outlive the session.
  RoomSession(boost::asio::io_context& io, SessionOptions options, RoomState& state, TransportFactory transports);
  /// The same with several servers (options.servers): `transports` is
  /// given the index of the server to connect to.
  RoomSession(boost::asio::io_context& io, SessionOptions options, RoomState& state,
              ServerTransportFactory transports);
  ~RoomSession();
  RoomSession(const RoomSession&) = delete;
  RoomSession& operator=(const RoomSession&) = delete;

  void start();
  /// Closes the connection and stops reconnecting (call on the io thread,
  /// e.g. through asio::post).
  void stop();
  /// Sends a chat line (from the io thread). A line "/look NAME" is no
  /// chat: it plays the look NAME saved with the person's avatar (command
  /// kind 6, PROTOCOL.md 8.2); a refusal comes back as an event.
  void chat(const std::string& text);
  /// A line the person typed (from the io thread): sent now when in the
  /// room, else with the first welcome, after the --say lines.
  void say(const std::string& text);
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
  void connection_lost(const std::string& why, NextStep next = after_drop());
  void end_connection();
  void upload_here(const std::string& why);
  void uploaded_here(std::size_t server, const ReuploadResult& result);
  void give_up(const std::string& why);
  bool could_upload_here() const;
  const AvatarCredentials& credentials_here() const;
  std::string server_name(std::size_t server) const;

  // What comes down.
  void on_message(std::span<const std::uint8_t> message);
  void on_stream_header(std::span<const std::uint8_t> message);
  void on_session_message(std::span<const std::uint8_t> message);
  codec::MessageError dispatch(codec::MessageType type, std::span<const std::uint8_t> message);
  template <class Message>
  codec::MessageError read_then(std::span<const std::uint8_t> bytes, void (RoomSession::*handle)(const Message&));
  void on_welcome(const codec::Welcome& welcome);
  void on_speaking(const codec::Speaking& speaking);
  void on_unit_morphs(const codec::UnitMorphs& morphs);
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
  ServerTransportFactory transports_;
  ServerRotation rotation_;
  /// Per server: the face's asset id and key there, once known (the first
  /// server's from the upload before the session; another's from an upload
  /// to it). A server without its own gets the last welcomed ones (the
  /// nodes of one cluster share avatars and the server key).
  std::vector<AvatarCredentials> credentials_;
  std::vector<bool> uploaded_to_;  ///< per server: the face went up there (one upload each)
  AvatarCredentials welcomed_credentials_;  ///< those of the last welcome
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
