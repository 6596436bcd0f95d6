#pragma once
// The protocol side of one room connection, whatever carries it
// (WebSocketSession, TcpSession): the hello and its checks, dispatching
// upstream messages to the room, limits and time-outs, and the bounded
// send queue the room delivers into. Runs on the connection's strand;
// deliver(), close() and joined() may be called from any thread.
#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/any_io_executor.hpp>
#include <boost/asio/steady_timer.hpp>

#include "fw/codec/messages.hpp"
#include "abuse_log.hpp"
#include "delivery_batch.hpp"
#include "room_connection.hpp"
#include "server_keys.hpp"
#include "session_services.hpp"
#include "socket_queue.hpp"
#include "subscriber_stream.hpp"

namespace fw::server {

class Room;

class ClientSession : public RoomConnection,
                      public BatchedWriter,
                      public std::enable_shared_from_this<ClientSession> {
 public:
  ClientSession(const SessionServices& services, boost::asio::any_io_executor executor, std::string peer);
  ~ClientSession() override;

  void deliver(SharedBytes message) override;
  std::size_t queued_bytes() const override { return queued_bytes_.load(std::memory_order_relaxed); }
  std::uint64_t bytes_written() const override { return bytes_written_.load(std::memory_order_relaxed); }
  void close(codec::CloseCode code, std::string reason) override;
  void joined(std::uint32_t avatar, SharedBytes welcome) override;
  /// The port is full and this connection had said nothing yet when a
  /// newcomer took its place (ConnectionShares): it closes at once, from
  /// any thread.
  void give_up_place();

 protected:
  /// The transport is connected: start the clock and read.
  void start();
  /// One whole upstream message.
  void on_message(std::span<const std::uint8_t> message);
  /// The transport refused or lost the connection; `code` and `reason` are
  /// for the log and, if the peer is still there, the closing message.
  void on_transport_error(codec::CloseCode code, const std::string& reason);
  /// The transport is gone (read error, EOF, shut down).
  void on_transport_closed();
  void on_write_done(bool ok, std::size_t bytes);
  void note_received(std::size_t bytes);
  /// A transport's control frame (a WebSocket ping or pong, answered by the
  /// transport itself) of `bytes`: counted as a message in the rate limits.
  /// False, and the connection closing with rate_limited, past them.
  bool note_control_frame(std::size_t bytes);

  /// The first message came (the hello, or what stands for it): from here
  /// on the connection carries something, and keeps its place on the port.
  virtual void on_first_message() {}
  /// What the transport's socket holds for the peer, or nullopt where it
  /// cannot tell (in memory): whether a person reads is seen there, not in
  /// our queue alone (socket_queue.hpp).
  virtual std::optional<SocketQueue> socket_queue() { return std::nullopt; }
  virtual void start_reading() = 0;
  /// Writes one message; calls on_write_done when finished. One at a time.
  virtual void start_write(const SharedBytes& message) = 0;
  /// Ends the connection after the closing message went out, or at once
  /// (`abort`: a write is stuck on a peer that does not read).
  virtual void shutdown_transport(codec::CloseCode code, const std::string& reason, bool abort) = 0;
  /// Whether the connection closes for something its peer did or failed to
  /// do (a violation, a flood, silence): then the closing message goes out
  /// and the connection ends limits::kQuickCloseLinger later, without
  /// reading what the peer still sends or waiting for its close handshake.
  /// A refused join from a well-behaved client is closed the ordinary way.
  bool closing_quickly() const { return quick_close_; }

  const SessionServices services_;  ///< a copy of the references: nothing a session holds dangles
  boost::asio::any_io_executor executor_;
  std::string peer_;

 private:
  void do_deliver(SharedBytes message);
  /// On the strand: queues what deliver() was given since the last time.
  void take_inbox();
  void write_delivered() override { take_inbox(); }
  const boost::asio::any_io_executor& strand() const override { return executor_; }
  void write_next();
  void do_close(codec::CloseCode code, std::string reason);
  void refill_tokens(std::chrono::steady_clock::time_point now);
  void handle_hello(std::span<const std::uint8_t> message);
  /// Why this server cannot admit `hello` (draining, bad room or name, token), or nullopt.
  std::optional<std::pair<codec::CloseCode, std::string>> refusal_of(const codec::Hello& hello) const;
  /// The uploaded package `hello` names, or a procedural face; nullopt if the package is unknown.
  AvatarLookup avatar_for(const codec::Hello& hello) const;
  StreamSettings stream_settings_for(const codec::Hello& hello) const;
  /// Closes the connection for its hello; `kind` counts and logs it as abuse.
  void refuse(codec::CloseCode code, const std::string& why, std::optional<Abuse> kind = std::nullopt);
  /// With --auth-secret: takes the hello's token for this connection, or
  /// refuses the hello (false) when another live connection holds it.
  bool claim_token(const codec::Hello& hello);
  void handle_joined_message(std::span<const std::uint8_t> message);
  void handle_resync(std::span<const std::uint8_t> message);
  void handle_chat(std::span<const std::uint8_t> message);
  void handle_command(std::span<const std::uint8_t> message);
  /// Why a face script may not be played now (the connection's or the
  /// address's script rate), nullopt when it may; takes its tokens.
  std::optional<std::string> script_refusal();
  /// Command kind 6: reads the look off the connection's strand (the store
  /// may wait for Redis), then sends its script into the room as a FACS
  /// command, so that a room (or the node that owns it) plays it as one.
  void play_look(codec::Command command);
  /// Answers command `request_id` here, without the room.
  void answer_command(std::uint32_t request_id, std::string error);
  void handle_set_rate(std::span<const std::uint8_t> message);
  void handle_ping(std::span<const std::uint8_t> message);
  void malformed(codec::MessageError error, const char* what);
  /// Closes for something the peer sent, counted as `kind` (and logged
  /// within the abuse log's lines a second).
  void protocol_error(codec::CloseCode code, const std::string& what, Abuse kind = Abuse::protocol_violation);
  void on_clock();
  /// Samples the socket: the person reads (read progress) if nothing waits
  /// in it, or the peer has room for what waits (its window is open); where
  /// the kernel does not tell the window, if it took bytes since the last
  /// sample (fewer are held than were held plus written since).
  void sample_read_progress(std::chrono::steady_clock::time_point now);
  std::chrono::milliseconds clock_period() const;
  /// Takes `cost` from a bucket the clock refills; false if it holds less.
  static bool take_token(double& tokens, double cost);

  enum class State { greeting, joining, joined, closing, closed };
  State state_ = State::greeting;
  std::shared_ptr<Room> room_;
  std::uint32_t avatar_ = 0;
  std::string resume_key_ = random_key();  ///< in the welcome: a reconnection that shows it takes over held_token_
  std::string held_token_;  ///< the join token this connection holds (TokenHolders)
  bool seated_ = false;  ///< the room seated avatar_
  std::vector<std::vector<std::uint8_t>> early_messages_;  ///< sent between hello and welcome
  /// What deliver() was given and the strand has not taken yet, in order;
  /// a job to take it is on its way while it holds anything (a room tick's
  /// DeliveryBatch, else a post of its own).
  std::mutex inbox_mutex_;
  std::vector<SharedBytes> inbox_;
  std::deque<SharedBytes> queue_;
  bool writing_ = false;
  std::atomic<std::size_t> queued_bytes_{0};
  std::atomic<std::uint64_t> bytes_written_{0};
  boost::asio::steady_timer clock_;
  std::chrono::steady_clock::time_point opened_, last_heard_, closing_since_, last_refill_;
  /// The last message other than a ping, and the last time bytes waiting
  /// for the peer moved (a write completed, or a wait began): who neither
  /// sends nor reads for SessionTimeouts::idle_person is let go.
  std::chrono::steady_clock::time_point last_sent_, read_progress_;
  /// The socket's unacknowledged bytes and bytes_written_ at the last
  /// sample; whether the transport tells them at all.
  std::size_t socket_queue_ = 0;
  std::uint64_t written_at_sample_ = 0;
  bool socket_known_ = false;
  double message_tokens_, byte_tokens_, chat_tokens_, script_tokens_;
  bool counted_ = false;
  bool transport_gone_ = false;
  codec::CloseCode close_code_ = codec::CloseCode::normal;
  std::string close_reason_;
  bool quick_close_ = false;  ///< closing_quickly()
  bool preview_ = false;      ///< the hello asked for a face-lab preview (PROTOCOL.md 5.16)
  /// The uploaded avatar the hello wore with its key (empty: a procedural
  /// face): whose saved looks command kind 6 plays.
  std::string worn_asset_;
};

}  // namespace fw::server
