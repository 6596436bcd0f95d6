#include "room_session.hpp"

#include <algorithm>

#include <boost/asio/error.hpp>

namespace fw::client {

namespace asio = boost::asio;
using Clock = std::chrono::steady_clock;

namespace {

// Closing codes after which trying again cannot help: the person must
// change something (token, room, name, avatar, client version).
bool refused_for_good(codec::CloseCode code) {
  switch (code) {
    case codec::CloseCode::protocol_error:
    case codec::CloseCode::message_too_large:
    case codec::CloseCode::unsupported_version:
    case codec::CloseCode::unauthorized:
    case codec::CloseCode::room_full:
    case codec::CloseCode::bad_request:
      return true;
    default:
      return false;
  }
}

}  // namespace

RoomSession::RoomSession(asio::io_context& io, SessionOptions options, RoomState& state, TransportFactory transports)
    : io_(io),
      options_(std::move(options)),
      state_(state),
      transports_(std::move(transports)),
      reconnect_timer_(io),
      housekeeping_timer_(io) {}

RoomSession::~RoomSession() = default;

std::chrono::milliseconds RoomSession::backoff(int failed_attempts) {
  const int doublings = std::clamp(failed_attempts - 1, 0, 4);
  return std::chrono::milliseconds(500 << doublings);
}

void RoomSession::start() {
  connect();
  schedule_housekeeping();
}

void RoomSession::stop() {
  stopped_ = true;
  ++connection_serial_;
  reconnect_timer_.cancel();
  housekeeping_timer_.cancel();
  if (transport_) transport_->close();
}

void RoomSession::event(const std::string& text) {
  if (options_.on_event) options_.on_event(text);
}

std::uint64_t RoomSession::now_us() const {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch()).count());
}

// ---------------------------------------------------------------------------
// A connection's life.

void RoomSession::connect() {
  if (stopped_) return;
  transport_ = transports_();
  const std::uint64_t serial = ++connection_serial_;
  transport_->connect(kConnectTimeoutS, [this, serial](boost::system::error_code ec) {
    if (serial != connection_serial_ || stopped_) return;
    on_connected(ec);
  });
}

void RoomSession::on_connected(boost::system::error_code ec) {
  if (ec) return connection_lost("cannot connect: " + ec.message());
  start_over();
  say_hello();
  read();
}

// Nothing of the last connection carries over but the avatars' packages
// (the welcome decides which stay).
void RoomSession::start_over() {
  {
    std::lock_guard lock(state_.mutex);
    state_.connection_started();
  }
  packages_.clear();
  server_clock_.reset();
  outbox_.clear();
  writing_ = false;
}

void RoomSession::say_hello() {
  codec::Hello hello;
  hello.room = options_.room;
  hello.name = options_.name;
  hello.avatar = options_.avatar_asset;
  hello.token = options_.token;
  hello.avatar_key = options_.avatar_key;
  // After a drop: the server may not have noticed it yet, and still hold
  // the token for the old connection; this key shows it is the same person.
  hello.resume = resume_key_;
  hello.max_bps = options_.max_bps;
  hello.timestamps = options_.timestamps;
  hello.own_package = options_.own_package != nullptr;
  send_message(hello);
}

void RoomSession::read() {
  const std::uint64_t serial = connection_serial_;
  transport_->read([this, serial](boost::system::error_code ec, std::span<const std::uint8_t> message) {
    if (serial != connection_serial_ || stopped_) return;
    if (ec) return connection_lost(ec == asio::error::eof ? "the server closed the connection" : ec.message());
    {
      std::lock_guard lock(state_.mutex);
      state_.stats.bytes_down(message.size() + transport_->framing_bytes(message.size(), false));
    }
    on_message(message);
    if (serial == connection_serial_ && !stopped_) read();
  });
}

void RoomSession::connection_lost(const std::string& why) {
  if (stopped_) return;
  ++connection_serial_;
  if (transport_) transport_->close();
  writing_ = false;
  outbox_.clear();
  {
    std::lock_guard lock(state_.mutex);
    state_.connection_lost();
  }
  ++failed_attempts_;
  const auto wait = backoff(failed_attempts_);
  event(why + "; reconnecting in " + std::to_string(wait.count()) + " ms");
  reconnect_timer_.expires_after(wait);
  reconnect_timer_.async_wait([this](boost::system::error_code ec) {
    if (!ec) connect();
  });
}

// ---------------------------------------------------------------------------
// What comes down.

void RoomSession::on_message(std::span<const std::uint8_t> message) {
  switch (codec::classify(message)) {
    case codec::MessageKind::session:
      return on_session_message(message);
    case codec::MessageKind::stream_header:
      return on_stream_header(message);
    case codec::MessageKind::room_frame:
      return on_room_frame(message, nullptr);
    case codec::MessageKind::resync_request:
    case codec::MessageKind::invalid:
      return connection_lost("the server sent a message a client does not expect (first byte " +
                             std::to_string(message.empty() ? -1 : message[0]) + ")");
  }
}

void RoomSession::on_stream_header(std::span<const std::uint8_t> message) {
  codec::StreamOptions stream;
  const codec::DecodeError error = codec::read_stream_header(message, stream);
  if (error != codec::DecodeError::ok)
    return connection_lost("bad stream header from the server: " + std::string(codec::describe(error)));
  std::lock_guard lock(state_.mutex);
  state_.stream_started(stream);
}

void RoomSession::on_session_message(std::span<const std::uint8_t> message) {
  const codec::MessageType type = codec::session_type(message);
  const codec::MessageError error = dispatch(type, message);
  if (error != codec::MessageError::ok)
    connection_lost("malformed message from the server (type " + std::to_string(static_cast<int>(type)) +
                    "): " + std::string(codec::describe(error)));
}

codec::MessageError RoomSession::dispatch(codec::MessageType type, std::span<const std::uint8_t> message) {
  using codec::MessageType;
  switch (type) {
    case MessageType::welcome: return read_then(message, &RoomSession::on_welcome);
    case MessageType::presence: return read_then(message, &RoomSession::on_presence);
    case MessageType::chat: return read_then(message, &RoomSession::on_chat);
    case MessageType::command_result: return read_then(message, &RoomSession::on_command_result);
    case MessageType::package_chunk: return read_then(message, &RoomSession::on_package_chunk);
    case MessageType::pong: return read_then(message, &RoomSession::on_pong);
    case MessageType::link_stats: return read_then(message, &RoomSession::on_link_stats);
    case MessageType::closing: return read_then(message, &RoomSession::on_closing);
    case MessageType::timed_room_frame: return read_then(message, &RoomSession::on_timed_room_frame);
    case MessageType::seats: return read_then(message, &RoomSession::on_seats);
    case MessageType::attention: return read_then(message, &RoomSession::on_attention);
    default: return codec::MessageError::wrong_type;  // an upstream message coming down
  }
}

// Reads one message of its type and, when it is well formed, handles it.
template <class Message>
codec::MessageError RoomSession::read_then(std::span<const std::uint8_t> bytes,
                                           void (RoomSession::*handle)(const Message&)) {
  Message message;
  const codec::MessageError error = codec::read_message(bytes, message);
  if (error == codec::MessageError::ok) (this->*handle)(message);
  return error;
}

void RoomSession::on_welcome(const codec::Welcome& welcome) {
  resume_key_ = welcome.resume;
  {
    std::lock_guard lock(state_.mutex);
    if (greeted_) state_.stats.reconnected();  // a welcome before this one: the link came back
    state_.welcomed(welcome, options_.own_package, Clock::now());
  }
  failed_attempts_ = 0;
  event("joined room " + welcome.room + " as avatar " + std::to_string(welcome.you) + " with " +
        std::to_string(welcome.avatars.size()) + " avatar(s) present");
  greet_once();
}

// The --say lines and the --emote go out after the first welcome only, not
// again after a reconnection.
void RoomSession::greet_once() {
  if (greeted_) return;
  greeted_ = true;
  for (const std::string& line : options_.say) chat(line);
  if (options_.emote.empty()) return;
  codec::Command command;
  command.request_id = ++command_serial_;
  command.kind = codec::Command::Kind::express;
  command.emotion = options_.emote;
  command.intensity = 1.0f;
  command.duration_ms = 3000;
  send_message(command);
}

void RoomSession::on_presence(const codec::Presence& presence) {
  std::lock_guard lock(state_.mutex);
  if (presence.change == codec::Presence::Change::joined) {
    state_.avatar_joined(presence.avatar);
    event(presence.avatar.name + " joined");
    return;
  }
  packages_.forget(presence.avatar.id);
  event(state_.avatar_left(presence.avatar.id) + " left");
}

void RoomSession::on_chat(const codec::Chat& chat) {
  std::lock_guard lock(state_.mutex);
  const std::string name = state_.chat_line(chat);
  event(name + ": " + chat.text);
}

void RoomSession::on_seats(const codec::Seats& seats) {
  std::lock_guard lock(state_.mutex);
  state_.seats_changed(seats);
}

void RoomSession::on_attention(const codec::Attention& attention) {
  std::lock_guard lock(state_.mutex);
  state_.attention_changed(attention);
}

void RoomSession::on_command_result(const codec::CommandResult& result) {
  if (!result.error.empty()) event("command refused: " + result.error);
}

void RoomSession::on_package_chunk(const codec::PackageChunk& chunk) {
  std::string problem;
  auto package = packages_.add(chunk, problem);
  if (!problem.empty()) event(problem);
  if (!package) return;
  std::lock_guard lock(state_.mutex);
  state_.package_arrived(std::move(*package), Clock::now());
}

void RoomSession::on_pong(const codec::Pong& pong) { server_clock_.pong(pong, now_us()); }

void RoomSession::on_link_stats(const codec::LinkStats& link) {
  std::lock_guard lock(state_.mutex);
  state_.server_link = link;
}

void RoomSession::on_closing(const codec::Closing& closing) {
  const std::string reason = closing.reason.empty() ? "no reason given" : closing.reason;
  if (!refused_for_good(closing.code)) return connection_lost("the server closed the connection: " + reason);
  {
    std::lock_guard lock(state_.mutex);
    state_.fatal_error = "the server refused this client: " + reason + " (closing code " +
                         std::to_string(static_cast<int>(closing.code)) + ")";
  }
  event("server: " + reason);
  stop();
}

void RoomSession::on_timed_room_frame(const codec::TimedRoomFrame& timed) { on_room_frame(timed.room_frame, &timed); }

void RoomSession::on_room_frame(std::span<const std::uint8_t> room_frame, const codec::TimedRoomFrame* timing) {
  const auto now = Clock::now();
  std::lock_guard lock(state_.mutex);
  const bool any = state_.decode_room_frame(room_frame, now);
  if (!any || !timing) return;
  if (const auto latency = server_clock_.elapsed_ms(timing->server_time_us, now_us())) state_.stats.latency_ms(*latency);
}

// ---------------------------------------------------------------------------
// What goes up.

void RoomSession::chat(const std::string& text) {
  codec::Chat chat;
  chat.text = text;
  send_message(chat);
}

void RoomSession::set_rate(std::uint32_t max_bps) {
  options_.max_bps = max_bps;
  send_message(codec::SetRate{max_bps});
}

template <class Message>
void RoomSession::send_message(const Message& message) {
  std::vector<std::uint8_t> bytes;
  codec::write_message(message, bytes);
  send(std::move(bytes));
}

void RoomSession::send(std::vector<std::uint8_t> message) {
  if (outbox_.size() >= kMaxOutbox) {
    event("upstream queue full: a message was dropped");
    return;
  }
  outbox_.push_back(std::make_shared<const std::vector<std::uint8_t>>(std::move(message)));
  write_next();
}

void RoomSession::write_next() {
  if (writing_ || outbox_.empty() || !transport_) return;
  writing_ = true;
  const std::uint64_t serial = connection_serial_;
  const auto message = outbox_.front();
  transport_->write(message, [this, serial, message](boost::system::error_code ec) {
    if (serial != connection_serial_ || stopped_) return;
    writing_ = false;
    if (ec) return connection_lost("sending failed: " + ec.message());
    {
      std::lock_guard lock(state_.mutex);
      state_.stats.bytes_up(message->size() + transport_->framing_bytes(message->size(), true));
    }
    outbox_.pop_front();
    write_next();
  });
}

void RoomSession::schedule_housekeeping() {
  if (stopped_) return;
  housekeeping_timer_.expires_after(kHousekeepingInterval);
  housekeeping_timer_.async_wait([this](boost::system::error_code ec) {
    if (ec || stopped_) return;
    housekeeping();
    schedule_housekeeping();
  });
}

// While in the room: a ping now and then (the clock offset, and the server
// wants to hear from a quiet client), and resync requests for decoders that
// wait for a key frame.
void RoomSession::housekeeping() {
  std::vector<std::uint32_t> need_keys;
  {
    std::lock_guard lock(state_.mutex);
    if (!state_.joined) return;
    need_keys = state_.decoder.needing_key_frames();
  }
  const auto now = Clock::now();
  ping_when_due(now);
  request_key_frames_when_due(now, std::move(need_keys));
}

void RoomSession::ping_when_due(Clock::time_point now) {
  if (now - last_ping_ < kPingInterval) return;
  last_ping_ = now;
  send_message(codec::Ping{++ping_nonce_, now_us()});
}

void RoomSession::request_key_frames_when_due(Clock::time_point now, std::vector<std::uint32_t> avatars) {
  if (avatars.empty() || now - last_resync_ < kResyncInterval) return;
  last_resync_ = now;
  if (avatars.size() > codec::kMaxRoomAvatars) avatars.resize(codec::kMaxRoomAvatars);
  std::vector<std::uint8_t> bytes;
  codec::write_resync_request(avatars, bytes);
  send(std::move(bytes));
}

}  // namespace fw::client
