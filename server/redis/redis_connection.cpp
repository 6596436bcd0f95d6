#include "redis_connection.hpp"

#include <algorithm>
#include <csignal>
#include <cstring>
#include <mutex>
#include <utility>

#include <boost/asio/ip/address.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <hiredis/async.h>
#include <hiredis/hiredis.h>
#include <spdlog/spdlog.h>

namespace fw::server {

// The Asio side of the adapter. The descriptor wraps hiredis' socket but
// never owns it: hiredis closes it, after its cleanup hook has released it.
struct RedisConnection::Io {
  explicit Io(const boost::asio::any_io_executor& executor)
      : socket(executor), timer(executor), resolver(executor) {}
  boost::asio::posix::stream_descriptor socket;
  boost::asio::steady_timer timer;
  boost::asio::ip::tcp::resolver resolver;
};

namespace {

// hiredis 0.14 writes with write(2), which raises SIGPIPE on a connection
// Redis has reset; that would end the whole process. A process that left
// SIGPIPE at its default gets it ignored (the write then fails with EPIPE
// and the connection is lost as it should be); one that set a handler of
// its own keeps it.
void ignore_sigpipe_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction current {};
    if (::sigaction(SIGPIPE, nullptr, &current) == 0 && current.sa_handler == SIG_DFL) std::signal(SIGPIPE, SIG_IGN);
  });
}

std::string milliseconds_text(std::chrono::milliseconds duration) {
  return std::to_string(duration.count()) + " ms";
}

bool is_text(const redisReply* reply, const char* text) {
  return reply->type == REDIS_REPLY_STRING && static_cast<std::size_t>(reply->len) == std::strlen(text) &&
         ::strncasecmp(reply->str, text, reply->len) == 0;
}

}  // namespace

std::shared_ptr<RedisConnection> RedisConnection::create(boost::asio::any_io_executor executor, RedisAddress address,
                                                         Options options) {
  ignore_sigpipe_once();
  return std::make_shared<RedisConnection>(CreateKey{}, std::move(executor), std::move(address), std::move(options));
}

RedisConnection::RedisConnection(CreateKey, boost::asio::any_io_executor executor, RedisAddress address,
                                 Options options)
    : executor_(std::move(executor)),
      address_(std::move(address)),
      options_(std::move(options)),
      io_(std::make_unique<Io>(executor_)) {}

RedisConnection::~RedisConnection() {
  // hiredis calls back while it frees the context (waiting commands with
  // NULL, the cleanup hook, the disconnect callback): with destroying_ set
  // they record nothing, and the cleanup hook releases the descriptor
  // before hiredis closes the socket.
  destroying_ = true;
  if (context_ != nullptr) redisAsyncFree(context_);
}

// ---- connect --------------------------------------------------------------

void RedisConnection::connect(StatusHandler done) {
  if (state_ != State::idle) {
    if (done)
      boost::asio::post(executor_, [done = std::move(done)] {
        done("connect() may be called once; make a new RedisConnection to connect again");
      });
    return;
  }
  state_ = State::connecting;
  connect_done_ = std::move(done);
  connect_deadline_ = Clock::now() + options_.connect_timeout;
  arm_timer(connect_deadline_);

  boost::system::error_code not_numeric;
  const auto ip = boost::asio::ip::make_address(address_.host, not_numeric);
  if (!not_numeric) {
    candidates_ = {ip.to_string()};
    try_next_address("");
    schedule_delivery();
    return;
  }
  // hiredis would resolve a name with a blocking getaddrinfo on this
  // thread; Asio's resolver does not hold the loop.
  io_->resolver.async_resolve(
      address_.host, std::to_string(address_.port),
      [weak = weak_from_this()](const boost::system::error_code& error,
                                const boost::asio::ip::tcp::resolver::results_type& results) {
        const auto self = weak.lock();
        if (!self || self->state_ != State::connecting) return;
        for (const auto& result : results) {
          const std::string candidate = result.endpoint().address().to_string();
          if (std::find(self->candidates_.begin(), self->candidates_.end(), candidate) == self->candidates_.end())
            self->candidates_.push_back(candidate);
        }
        if (error || self->candidates_.empty())
          self->fail_connect("cannot resolve the host name '" + self->address_.host + "': " +
                             (error ? error.message() : "no address"));
        else
          self->try_next_address("");
        self->deliver();
      });
}

// A name may have several addresses ("localhost": ::1 and 127.0.0.1, and
// Redis may listen on one only): each is tried in turn, within the one
// connect deadline.
void RedisConnection::try_next_address(const std::string& why) {
  if (next_candidate_ >= candidates_.size()) return fail_connect(why);
  ++attempt_;
  start_context(candidates_[next_candidate_++]);
}

void RedisConnection::start_context(const std::string& ip) {
  // Which address failed, when the host is a name with several.
  const std::string where = ip == address_.host ? std::string() : ip + ": ";
  redisAsyncContext* context = redisAsyncConnect(ip.c_str(), address_.port);
  if (context == nullptr) return fail_connect("hiredis could not allocate a connection");
  if (context->err != 0) {
    const std::string why = where + context->c.errstr;
    redisAsyncFree(context);
    return try_next_address(why);
  }
  boost::system::error_code error;
  io_->socket.assign(context->c.fd, error);
  if (error) {
    redisAsyncFree(context);  // no hooks yet: hiredis only closes its socket
    return fail_connect("cannot watch the socket: " + error.message());
  }
  last_error_ = where + "the connection closed before Redis answered";
  context_ = context;
  context->data = this;
  redisAsyncSetConnectCallback(context, &on_hiredis_connect);
  redisAsyncSetDisconnectCallback(context, &on_hiredis_disconnect);
  context->ev.data = this;
  context->ev.addRead = &hook_add_read;
  context->ev.delRead = &hook_del_read;
  context->ev.addWrite = &hook_add_write;
  context->ev.delWrite = &hook_del_write;
  context->ev.cleanup = &hook_cleanup;
  // hiredis learns that the connect finished from the first writable
  // event; the handshake's commands wait in its buffer until then.
  want_write(true);

  if (!address_.password.empty()) {
    std::vector<std::string> auth{"AUTH"};
    if (!address_.username.empty()) auth.push_back(address_.username);
    auth.push_back(address_.password);
    send_handshake(std::move(auth), "AUTH", false);
  }
  if (!options_.client_name.empty())
    send_handshake({"CLIENT", "SETNAME", options_.client_name}, "CLIENT SETNAME " + options_.client_name, false);
  if (address_.db != 0)
    send_handshake({"SELECT", std::to_string(address_.db)}, "SELECT " + std::to_string(address_.db), true);
  else
    send_handshake({"PING"}, "PING", true);
}

void RedisConnection::send_handshake(std::vector<std::string> args, std::string what, bool last) {
  if (!send(args, &on_hiredis_reply)) return fail_connect("hiredis refused the " + what);
  // Runs from deliver(), while the object is alive: `this` is safe.
  waiting_.back().handler = [this, what = std::move(what), last, attempt = attempt_](const RedisReply* reply) {
    if (state_ != State::connecting || attempt != attempt_) return;
    if (reply == nullptr) return try_next_address(last_error_);  // this address failed
    if (reply->is_error()) return fail_connect(what + " was refused: " + describe(*reply));
    if (last) become_ready();
  };
}

void RedisConnection::become_ready() {
  state_ = State::ready;
  push({Delivery::Kind::connect_done, {}, {}, {}, {}});
  // The connect deadline may still be armed; on_timer moves on to commands.
}

void RedisConnection::fail_connect(const std::string& why) {
  if (state_ != State::connecting) return;
  state_ = State::ended;
  io_->resolver.cancel();
  free_context();
  push({Delivery::Kind::connect_done, {}, {}, "cannot connect to " + to_string(address_) + ": " + why, {}});
}

// ---- the connection -------------------------------------------------------

bool RedisConnection::connected() const { return state_ == State::ready && context_ != nullptr; }

void RedisConnection::on_lost(StatusHandler handler) { lost_handler_ = std::move(handler); }

void RedisConnection::on_message(MessageHandler handler) { message_handler_ = std::move(handler); }

std::size_t RedisConnection::pending_output() const {
  return context_ != nullptr ? sdslen(context_->c.obuf) : 0;
}

bool RedisConnection::send(std::vector<std::string>& args, void (*callback)(redisAsyncContext*, void*, void*)) {
  if (context_ == nullptr || args.empty()) return false;
  argv_.clear();
  argv_lengths_.clear();
  for (const auto& arg : args) {
    argv_.push_back(arg.data());
    argv_lengths_.push_back(arg.size());
  }
  // hiredis copies the arguments into its output buffer before it returns.
  if (redisAsyncCommandArgv(context_, callback, nullptr, static_cast<int>(argv_.size()), argv_.data(),
                            argv_lengths_.data()) != REDIS_OK)
    return false;
  // Every command with this callback is answered in order (hiredis keeps
  // one callback list for them), so the front of waiting_ is always the
  // command whose answer comes next.
  if (callback == &on_hiredis_reply) waiting_.push_back({{}, Clock::now()});
  return true;
}

void RedisConnection::command(std::vector<std::string> args, ReplyHandler handler) {
  if (subscriber_) {
    spdlog::warn("{}: a command on a subscribed connection is not sent (use another connection)",
                 to_string(address_));
  } else if (connected() && send(args, &on_hiredis_reply)) {
    waiting_.back().handler = std::move(handler);
    if (!timer_armed_) arm_timer(waiting_.back().sent + options_.command_timeout);
    return;
  }
  if (handler) {
    push({Delivery::Kind::reply, std::move(handler), std::nullopt, {}, {}});
    schedule_delivery();
  }
}

void RedisConnection::subscribe(const std::vector<std::string>& channels) {
  subscription_command("SUBSCRIBE", channels, true);
}
void RedisConnection::unsubscribe(const std::vector<std::string>& channels) {
  subscription_command("UNSUBSCRIBE", channels, false);
}
void RedisConnection::psubscribe(const std::vector<std::string>& patterns) {
  subscription_command("PSUBSCRIBE", patterns, true);
}
void RedisConnection::punsubscribe(const std::vector<std::string>& patterns) {
  subscription_command("PUNSUBSCRIBE", patterns, false);
}

void RedisConnection::subscription_command(const char* verb, const std::vector<std::string>& names,
                                           bool confirmed) {
  if (!connected()) {
    spdlog::warn("{}: {} while not connected is ignored", to_string(address_), verb);
    return;
  }
  if (confirmed && names.empty()) return;
  if (!confirmed && !subscriber_) return;  // hiredis refuses an UNSUBSCRIBE before any SUBSCRIBE
  std::vector<std::string> args{verb};
  args.insert(args.end(), names.begin(), names.end());
  // hiredis keeps the callback of a (P)SUBSCRIBE for every message of its
  // channels; (P)UNSUBSCRIBE registers none (each channel's confirmation
  // comes through the callback the channel had).
  if (!send(args, &on_hiredis_subscription)) return;
  subscriber_ = true;
  if (!confirmed) return;
  // Each channel or pattern is confirmed by a message of its own: each
  // one counts as a command waiting for command_timeout.
  const auto now = Clock::now();
  subscriptions_unconfirmed_.insert(subscriptions_unconfirmed_.end(), names.size(), now);
  if (!timer_armed_) arm_timer(now + options_.command_timeout);
}

void RedisConnection::close() {
  if (state_ == State::connecting)
    fail_connect("closed before it was connected");
  else if (state_ == State::ready)
    lose("closed by this node");
  else
    state_ = State::ended;
  schedule_delivery();
}

void RedisConnection::lose(const std::string& why) {
  if (state_ != State::ready) return;
  state_ = State::ended;
  free_context();  // every waiting command's nullptr is queued first
  push({Delivery::Kind::lost, {}, {}, "lost the connection to " + to_string(address_) + ": " + why, {}});
}

void RedisConnection::free_context() {
  if (context_ == nullptr) return;
  // Never from inside hiredis (handlers run after it returned), so the
  // context is freed now, not deferred to the end of a callback.
  redisAsyncFree(context_);
  context_ = nullptr;
}

std::optional<RedisConnection::Clock::time_point> RedisConnection::oldest_unanswered() const {
  std::optional<Clock::time_point> oldest;
  if (!waiting_.empty()) oldest = waiting_.front().sent;
  if (!subscriptions_unconfirmed_.empty() && (!oldest || subscriptions_unconfirmed_.front() < *oldest))
    oldest = subscriptions_unconfirmed_.front();
  return oldest;
}

void RedisConnection::arm_timer(Clock::time_point at) {
  timer_armed_ = true;
  io_->timer.expires_at(at);
  io_->timer.async_wait([weak = weak_from_this()](const boost::system::error_code& error) {
    const auto self = weak.lock();
    if (!self || error) return;
    self->timer_armed_ = false;
    self->on_timer();
    self->deliver();
  });
}

// One timer serves both deadlines: the connect's, then the oldest
// unanswered command's. Sending a command only arms it when it is idle:
// an armed timer is never later than the new command's deadline.
void RedisConnection::on_timer() {
  const auto now = Clock::now();
  if (state_ == State::connecting) {
    if (now >= connect_deadline_)
      fail_connect("no answer within " + milliseconds_text(options_.connect_timeout));
    else
      arm_timer(connect_deadline_);
    return;
  }
  if (state_ != State::ready) return;
  const auto oldest = oldest_unanswered();
  if (!oldest) return;
  if (now >= *oldest + options_.command_timeout)
    lose("no answer within " + milliseconds_text(options_.command_timeout));
  else
    arm_timer(*oldest + options_.command_timeout);
}

// ---- deliveries -----------------------------------------------------------

void RedisConnection::push(Delivery delivery) { deliveries_.push_back(std::move(delivery)); }

void RedisConnection::schedule_delivery() {
  if (delivery_posted_ || delivering_ || deliveries_.empty()) return;
  delivery_posted_ = true;
  boost::asio::post(executor_, [self = shared_from_this()] {
    self->delivery_posted_ = false;
    self->deliver();
  });
}

// Runs the users' handlers, never from inside hiredis. Its callers hold a
// reference to the connection, so a handler may drop the last one of its
// own; a handler that calls close() adds its deliveries to this same loop.
void RedisConnection::deliver() {
  if (delivering_) return;
  delivering_ = true;
  struct Done {
    bool& flag;
    ~Done() { flag = false; }
  } done{delivering_};
  while (!deliveries_.empty()) {
    Delivery delivery = std::move(deliveries_.front());
    deliveries_.pop_front();
    switch (delivery.kind) {
      case Delivery::Kind::reply:
        if (delivery.handler) delivery.handler(delivery.reply ? &*delivery.reply : nullptr);
        break;
      case Delivery::Kind::message:
        if (message_handler_) message_handler_(delivery.first, delivery.second);
        break;
      case Delivery::Kind::connect_done:
        if (connect_done_) std::exchange(connect_done_, {})(delivery.first);
        break;
      case Delivery::Kind::lost:
        if (lost_handler_) std::exchange(lost_handler_, {})(delivery.first);
        break;
    }
  }
}

// ---- the adapter ----------------------------------------------------------
// hiredis says when it wants to read or write (the hooks below, called
// again and again: they are idempotent); one wait each way is kept pending
// on the socket while it does, and each completed wait hands the socket
// back to hiredis. Asio starts every wait with the descriptor's readiness
// checked anew (epoll_ctl MOD), so readiness that came while no wait was
// pending (hiredis reads 16 KiB at a time) is not lost.

void RedisConnection::want_read(bool wanted) {
  want_read_ = wanted;
  if (wanted && !read_waiting_) wait_readable();
}

void RedisConnection::want_write(bool wanted) {
  want_write_ = wanted;
  if (wanted && !write_waiting_) wait_writable();
}

void RedisConnection::wait_readable() {
  read_waiting_ = true;
  io_->socket.async_wait(
      boost::asio::posix::stream_descriptor::wait_read,
      [weak = weak_from_this(), socket = socket_generation_](const boost::system::error_code& error) {
        if (const auto self = weak.lock()) self->socket_ready(true, socket, error);
      });
}

void RedisConnection::wait_writable() {
  write_waiting_ = true;
  io_->socket.async_wait(
      boost::asio::posix::stream_descriptor::wait_write,
      [weak = weak_from_this(), socket = socket_generation_](const boost::system::error_code& error) {
        if (const auto self = weak.lock()) self->socket_ready(false, socket, error);
      });
}

void RedisConnection::socket_ready(bool read, unsigned socket, const boost::system::error_code& error) {
  if (socket != socket_generation_) return;  // a wait on an earlier socket, released
  bool& waiting = read ? read_waiting_ : write_waiting_;
  const bool& wanted = read ? want_read_ : want_write_;
  waiting = false;
  if (error || context_ == nullptr) return;
  // hiredis may free the context in here (Redis gone): its cleanup hook
  // clears context_. While it still wants the socket it asks again
  // (addRead, addWrite), which starts the next wait.
  if (wanted) read ? redisAsyncHandleRead(context_) : redisAsyncHandleWrite(context_);
  if (context_ != nullptr && wanted && !waiting) read ? wait_readable() : wait_writable();
  deliver();
}

// hiredis is about to close its socket and free the context. The waits on
// it end aborted; the next address's socket (a name with several) starts
// afresh.
void RedisConnection::detach() {
  want_read_ = want_write_ = false;
  read_waiting_ = write_waiting_ = false;
  ++socket_generation_;
  context_ = nullptr;
  if (io_->socket.is_open()) io_->socket.release();  // cancels the waits; hiredis closes the socket
}

void RedisConnection::hook_add_read(void* self) { static_cast<RedisConnection*>(self)->want_read(true); }
void RedisConnection::hook_del_read(void* self) { static_cast<RedisConnection*>(self)->want_read(false); }
void RedisConnection::hook_add_write(void* self) { static_cast<RedisConnection*>(self)->want_write(true); }
void RedisConnection::hook_del_write(void* self) { static_cast<RedisConnection*>(self)->want_write(false); }
void RedisConnection::hook_cleanup(void* self) { static_cast<RedisConnection*>(self)->detach(); }

// ---- hiredis' callbacks ---------------------------------------------------
// They only record: what users see is queued for deliver().

void RedisConnection::on_hiredis_connect(const redisAsyncContext* context, int status) {
  auto* self = static_cast<RedisConnection*>(context->data);
  // hiredis 0.14 has not copied the error to context->errstr yet here.
  if (status != REDIS_OK && !self->destroying_) {
    const std::string ip = context->c.tcp.host != nullptr ? context->c.tcp.host : "";
    self->last_error_ = (ip.empty() || ip == self->address_.host ? "" : ip + ": ") + context->c.errstr;
  }
}

void RedisConnection::on_hiredis_disconnect(const redisAsyncContext* context, int status) {
  auto* self = static_cast<RedisConnection*>(context->data);
  self->context_ = nullptr;  // hiredis frees it when this returns
  if (self->destroying_) return;
  const std::string why = status == REDIS_OK ? "closed" : context->c.errstr;
  if (self->state_ == State::connecting) {
    self->last_error_ = why;  // the handshake's nullptr reports it
  } else if (self->state_ == State::ready) {
    self->state_ = State::ended;
    self->push({Delivery::Kind::lost, {}, {}, "lost the connection to " + to_string(self->address_) + ": " + why, {}});
  }
}

void RedisConnection::on_hiredis_reply(redisAsyncContext* context, void* reply, void*) {
  static_cast<RedisConnection*>(context->data)->took_reply(static_cast<const redisReply*>(reply));
}

void RedisConnection::on_hiredis_subscription(redisAsyncContext* context, void* reply, void*) {
  static_cast<RedisConnection*>(context->data)->took_subscription_message(static_cast<const redisReply*>(reply));
}

void RedisConnection::took_reply(const redisReply* reply) {
  if (destroying_ || waiting_.empty()) return;
  Waiting waiting = std::move(waiting_.front());
  waiting_.pop_front();
  if (!waiting.handler) return;  // nobody reads it: no copy
  push({Delivery::Kind::reply, std::move(waiting.handler),
        reply != nullptr ? std::optional<RedisReply>(copy_reply(*reply)) : std::nullopt, {}, {}});
}

// Pub/sub arrays: ["message", channel, payload], ["pmessage", pattern,
// channel, payload], and the confirmations ["subscribe", channel, count]
// ("psubscribe", "unsubscribe", "punsubscribe"). NULL when the connection
// goes: the waiting commands' nullptrs tell the rest.
void RedisConnection::took_subscription_message(const redisReply* reply) {
  if (destroying_ || reply == nullptr || reply->type != REDIS_REPLY_ARRAY || reply->elements < 3) return;
  const redisReply* const* element = reply->element;
  if (is_text(element[0], "message") && element[1]->type == REDIS_REPLY_STRING &&
      element[2]->type == REDIS_REPLY_STRING) {
    push({Delivery::Kind::message, {}, {}, std::string(element[1]->str, element[1]->len),
          std::string(element[2]->str, element[2]->len)});
  } else if (is_text(element[0], "pmessage") && reply->elements >= 4 && element[2]->type == REDIS_REPLY_STRING &&
             element[3]->type == REDIS_REPLY_STRING) {
    push({Delivery::Kind::message, {}, {}, std::string(element[2]->str, element[2]->len),
          std::string(element[3]->str, element[3]->len)});
  } else if (is_text(element[0], "subscribe") || is_text(element[0], "psubscribe")) {
    if (!subscriptions_unconfirmed_.empty()) subscriptions_unconfirmed_.pop_front();
  }
}

}  // namespace fw::server
