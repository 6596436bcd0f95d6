#pragma once
// One connection to Redis, on the node's own Boost.Asio loop: hiredis' async
// API parses and frames, and a small adapter waits on hiredis' socket with
// Asio (no thread of its own). Replies, pub/sub messages and the news that
// the connection is lost reach their handlers on the caller's executor,
// after hiredis has returned, so a handler may do anything (send the next
// command, close the connection, drop the last reference to it).
//
// A connection is made once: when it is lost (Redis gone or restarted, a
// command unanswered for command_timeout, close()), make a new one.
#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <boost/asio/any_io_executor.hpp>
#include <boost/system/error_code.hpp>

#include "redis_reply.hpp"
#include "redis_url.hpp"

struct redisAsyncContext;  // hiredis
struct redisReply;

namespace fw::server {

struct RedisConnectionOptions {
  /// From connect() to the handshake's last answer (AUTH, CLIENT SETNAME,
  /// SELECT or PING): a host that drops packets or a stopped Redis.
  std::chrono::milliseconds connect_timeout{2000};
  /// The longest a command (or a subscription's confirmation) may wait for
  /// its answer before the connection is taken for lost; hiredis 0.14 has no
  /// time-out of its own.
  std::chrono::milliseconds command_timeout{3000};
  /// Sent as CLIENT SETNAME at connect, so that CLIENT LIST names the node;
  /// empty: none. Redis refuses spaces in it.
  std::string client_name;
};

class RedisConnection : public std::enable_shared_from_this<RedisConnection> {
 public:
  using Options = RedisConnectionOptions;
  using ReplyHandler = std::function<void(const RedisReply*)>;
  using MessageHandler = std::function<void(std::string_view channel, std::string_view payload)>;
  using StatusHandler = std::function<void(const std::string&)>;

  /// Every callback runs on `executor` (a strand, or a single-threaded
  /// io_context's executor); the object is used from it only.
  static std::shared_ptr<RedisConnection> create(boost::asio::any_io_executor executor, RedisAddress address,
                                                 Options options = {});
  /// Destroying a connection closes it at once. The handlers of commands
  /// still waiting are dropped uncalled (they may refer to an owner that is
  /// going away too); on_lost is not called. close() first to have them
  /// called with nullptr.
  ~RedisConnection();
  RedisConnection(const RedisConnection&) = delete;
  RedisConnection& operator=(const RedisConnection&) = delete;

  /// Resolves the host (Asio's resolver, when it is a name), connects
  /// without blocking (hiredis async connect) and runs the handshake: AUTH
  /// when the address has a password, CLIENT SETNAME when the options name
  /// the client, SELECT the db (PING for db 0), all within connect_timeout.
  /// done("") on success; done(why) if it failed (refused, timed out, a
  /// handshake command refused), the why naming the address. Once only.
  void connect(StatusHandler done);
  /// Once, when an established connection is lost (Redis gone, restarted,
  /// a command not answered within command_timeout, close()). Every command
  /// still waiting gets its handler called with nullptr first. Set it
  /// before the connection can be lost.
  void on_lost(StatusHandler handler);
  /// Connected and not lost: commands are sent.
  bool connected() const;

  /// A binary-safe command (redisAsyncCommandArgv): {"SET", key, value}.
  /// Commands are pipelined and answered in order. The handler gets the
  /// reply, or nullptr when the connection is not up, is a subscriber, or
  /// is lost before the answer (posted, never called inline from
  /// command()). The handler may be empty.
  void command(std::vector<std::string> args, ReplyHandler handler = {});

  /// Pub/sub (use a connection only for this: once it subscribed, command()
  /// answers nullptr): SUBSCRIBE, UNSUBSCRIBE, PSUBSCRIBE, PUNSUBSCRIBE. An
  /// empty list unsubscribes from every channel (or pattern). Every
  /// message of a subscribed channel or pattern goes to the message handler
  /// (channel, payload: binary-safe; for a pattern, the channel the message
  /// was published on). Ignored when not connected. A subscription not
  /// confirmed within command_timeout loses the connection.
  void subscribe(const std::vector<std::string>& channels);
  void unsubscribe(const std::vector<std::string>& channels);
  void psubscribe(const std::vector<std::string>& patterns);
  void punsubscribe(const std::vector<std::string>& patterns);
  void on_message(MessageHandler handler);

  /// Bytes hiredis still has to write (its output buffer): for back-pressure.
  std::size_t pending_output() const;
  /// Commands sent and not answered yet.
  std::size_t commands_waiting() const { return waiting_.size(); }
  const RedisAddress& address() const { return address_; }

  /// Drops the connection at once: waiting handlers get nullptr, then
  /// on_lost ("closed") if it was established, or connect's done if it
  /// was still connecting. All posted.
  void close();

 private:
  struct CreateKey {};

 public:
  RedisConnection(CreateKey, boost::asio::any_io_executor executor, RedisAddress address, Options options);

 private:
  enum class State { idle, connecting, ready, ended };
  using Clock = std::chrono::steady_clock;

  struct Waiting {
    ReplyHandler handler;
    Clock::time_point sent;
  };
  // Work for a user's handler, queued while hiredis runs and run after it
  // returned, in the order hiredis produced it.
  struct Delivery {
    enum class Kind { reply, message, connect_done, lost } kind;
    ReplyHandler handler;             // reply
    std::optional<RedisReply> reply;  // reply; nullopt: nullptr
    std::string first;                // message: channel; connect_done, lost: the why
    std::string second;               // message: payload
  };
  struct Io;  // the Asio objects, kept out of this header

  // connect
  void try_next_address(const std::string& why);
  void start_context(const std::string& ip);
  void send_handshake(std::vector<std::string> args, std::string what, bool last);
  void become_ready();
  void fail_connect(const std::string& why);
  // the connection
  bool send(std::vector<std::string>& args, void (*callback)(redisAsyncContext*, void*, void*));
  void subscription_command(const char* verb, const std::vector<std::string>& names, bool confirmed);
  void lose(const std::string& why);
  void free_context();
  void arm_timer(Clock::time_point at);
  void on_timer();
  std::optional<Clock::time_point> oldest_unanswered() const;
  // deliveries
  void push(Delivery delivery);
  void schedule_delivery();
  void deliver();
  // the adapter: hiredis' event hooks
  void want_read(bool wanted);
  void want_write(bool wanted);
  void wait_readable();
  void wait_writable();
  void socket_ready(bool read, unsigned socket, const boost::system::error_code& error);
  void detach();
  static void hook_add_read(void* self);
  static void hook_del_read(void* self);
  static void hook_add_write(void* self);
  static void hook_del_write(void* self);
  static void hook_cleanup(void* self);
  // hiredis' callbacks
  static void on_hiredis_connect(const redisAsyncContext* context, int status);
  static void on_hiredis_disconnect(const redisAsyncContext* context, int status);
  static void on_hiredis_reply(redisAsyncContext* context, void* reply, void* privdata);
  static void on_hiredis_subscription(redisAsyncContext* context, void* reply, void* privdata);
  void took_reply(const redisReply* reply);
  void took_subscription_message(const redisReply* reply);

  boost::asio::any_io_executor executor_;
  RedisAddress address_;
  Options options_;
  std::unique_ptr<Io> io_;
  redisAsyncContext* context_ = nullptr;  // null before connect and once hiredis freed it
  State state_ = State::idle;
  StatusHandler connect_done_;
  StatusHandler lost_handler_;
  MessageHandler message_handler_;
  std::string last_error_;  // hiredis' words for a failed connect, for connect's done
  std::vector<std::string> candidates_;  // the host's addresses, tried in turn
  std::size_t next_candidate_ = 0;
  int attempt_ = 0;  // which of them the handshake under way belongs to
  std::deque<Waiting> waiting_;
  std::deque<Clock::time_point> subscriptions_unconfirmed_;
  std::deque<Delivery> deliveries_;
  std::vector<const char*> argv_;  // reused by send()
  std::vector<std::size_t> argv_lengths_;
  Clock::time_point connect_deadline_{};
  bool subscriber_ = false;
  bool want_read_ = false, want_write_ = false;
  bool read_waiting_ = false, write_waiting_ = false;
  unsigned socket_generation_ = 0;  // which socket a wait was for
  bool timer_armed_ = false;
  bool delivering_ = false, delivery_posted_ = false;
  bool destroying_ = false;
};

}  // namespace fw::server
