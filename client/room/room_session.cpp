#include "room_session.hpp"

#include <algorithm>

#include <boost/asio/error.hpp>

namespace fw::client {

namespace asio = boost::asio;
using Clock = std::chrono::steady_clock;

RoomSession::RoomSession(asio::io_context& io, SessionOptions options, RoomState& state, TransportFactory transports)
    : RoomSession(io, std::move(options), state,
                  [transports = std::move(transports)](std::size_t) { return transports(); }) {}

RoomSession::RoomSession(asio::io_context& io, SessionOptions options, RoomState& state,
                         ServerTransportFactory transports)
    : io_(io),
      options_(std::move(options)),
      state_(state),
      transports_(std::move(transports)),
      rotation_(options_.servers.size(), options_.first_server),
      credentials_(rotation_.count()),
      uploaded_to_(rotation_.count(), false),
      welcomed_credentials_{options_.avatar_asset, options_.avatar_key},
      reconnect_timer_(io),
      housekeeping_timer_(io) {
  if (options_.avatar_asset.empty()) return;
  // The face went up to the first server before the session began.
  credentials_[rotation_.current()] = welcomed_credentials_;
  uploaded_to_[rotation_.current()] = true;
}

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

std::string RoomSession::server_name(std::size_t server) const {
  return server < options_.servers.size() ? options_.servers[server] : "the server";
}

void RoomSession::connect() {
  if (stopped_) return;
  {
    std::lock_guard lock(state_.mutex);
    state_.server = server_name(rotation_.current());
  }
  transport_ = transports_(rotation_.current());
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
  const AvatarCredentials& face = credentials_here();
  hello.avatar = face.asset;
  hello.token = options_.token;
  hello.avatar_key = face.key;
  // After a drop: the server may not have noticed it yet, and still hold
  // the token for the old connection; this key shows it is the same person.
  hello.resume = resume_key_;
  hello.max_bps = options_.max_bps;
  hello.timestamps = options_.timestamps;
  hello.own_package = options_.own_package != nullptr;
  hello.language = options_.language;
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

const AvatarCredentials& RoomSession::credentials_here() const {
  const AvatarCredentials& own = credentials_[rotation_.current()];
  return own.asset.empty() ? welcomed_credentials_ : own;
}

// The connection (or the attempt) is over; what comes of it is the caller's.
void RoomSession::end_connection() {
  ++connection_serial_;
  if (transport_) transport_->close();
  writing_ = false;
  outbox_.clear();
  std::lock_guard lock(state_.mutex);
  state_.connection_lost();
}

void RoomSession::connection_lost(const std::string& why, NextStep next) {
  if (stopped_) return;
  end_connection();
  ++failed_attempts_;
  const auto wait = backoff(failed_attempts_);
  if (next == NextStep::next_server && rotation_.count() > 1) {
    const std::size_t to = rotation_.move_on();
    event(why + "; moving to " + server_name(to) + " (server " + std::to_string(to + 1) + " of " +
          std::to_string(rotation_.count()) + ") in " + std::to_string(wait.count()) + " ms");
  } else {
    event(why + "; reconnecting in " + std::to_string(wait.count()) + " ms");
  }
  reconnect_timer_.expires_after(wait);
  reconnect_timer_.async_wait([this](boost::system::error_code ec) {
    if (!ec) connect();
  });
}

bool RoomSession::could_upload_here() const {
  return options_.reupload && !uploaded_to_[rotation_.current()];
}

// This server refused the face as a server that never had it would: it
// gets the upload once, and the hello again with what it answers.
void RoomSession::upload_here(const std::string& why) {
  end_connection();
  const std::size_t server = rotation_.current();
  uploaded_to_[server] = true;
  event(server_name(server) + " refused the face (" + why + "); uploading it there");
  const std::uint64_t serial = connection_serial_;
  options_.reupload(server, [this, serial, server](ReuploadResult result) {
    if (serial != connection_serial_ || stopped_) return;
    uploaded_here(server, result);
  });
}

void RoomSession::uploaded_here(std::size_t server, const ReuploadResult& result) {
  if (result.ok) {
    credentials_[server] = result.credentials;
    event("uploaded the face to " + server_name(server));
    return connect();
  }
  if (!result.try_elsewhere) return give_up("uploading the face to " + server_name(server) + ": " + result.error);
  uploaded_to_[server] = false;  // it never got the face: when the list comes round to it, it is tried again
  connection_lost("uploading the face to " + server_name(server) + ": " + result.error, NextStep::next_server);
}

// A refusal that trying again (here or elsewhere) cannot fix.
void RoomSession::give_up(const std::string& why) {
  {
    std::lock_guard lock(state_.mutex);
    state_.fatal_error = why;
  }
  stop();
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
    case MessageType::speaking: return read_then(message, &RoomSession::on_speaking);
    case MessageType::unit_morphs: return read_then(message, &RoomSession::on_unit_morphs);
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
  welcomed_credentials_ = credentials_here();
  std::vector<std::string> mute_notices;  // said once, on entering the room
  {
    std::lock_guard lock(state_.mutex);
    if (greeted_) state_.stats.reconnected();  // a welcome before this one: the link came back
    state_.welcomed(welcome, options_.own_package, Clock::now());
    if (!greeted_) mute_notices = state_.mutes.notices(welcome.avatars, welcome.you);
  }
  failed_attempts_ = 0;
  event("joined room " + welcome.room + " as avatar " + std::to_string(welcome.you) + " with " +
        std::to_string(welcome.avatars.size()) + " avatar(s) present" +
        (rotation_.count() > 1 ? " on " + server_name(rotation_.current()) : ""));
  for (const std::string& notice : mute_notices) event(notice);
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
    event(presence.avatar.name + " joined" + (state_.muted(presence.avatar.id) ? " (muted for you)" : ""));
    return;
  }
  packages_.forget(presence.avatar.id);
  event(state_.avatar_left(presence.avatar.id) + " left");
}

void RoomSession::on_chat(const codec::Chat& chat) {
  std::lock_guard lock(state_.mutex);
  const bool muted = state_.muted(chat.from);
  const std::string name = state_.chat_line(chat);
  if (!muted) event(name + ": " + chat.text);
}

void RoomSession::on_speaking(const codec::Speaking& speaking) {
  std::lock_guard lock(state_.mutex);
  if (const auto line = state_.line_begun(speaking, Clock::now())) event(*line);
}

void RoomSession::on_unit_morphs(const codec::UnitMorphs& morphs) {
  std::lock_guard lock(state_.mutex);
  state_.unit_morphs_arrived(morphs);
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
  switch (const NextStep next = after_closing(closing.code, could_upload_here())) {
    case NextStep::upload_here: return upload_here(reason);
    case NextStep::stop:
      event("server: " + reason);
      return give_up("the server refused this client: " + reason + " (closing code " +
                     std::to_string(static_cast<int>(closing.code)) + ")");
    default: return connection_lost("the server closed the connection: " + reason, next);
  }
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
  constexpr std::string_view kLook = "/look ";
  if (text.starts_with(kLook)) {
    const std::string name = text.substr(kLook.size());
    if (name.empty() || name.size() > codec::kMaxLookNameBytes)
      return event("/look takes the name of a look saved with your avatar (1 to " +
                   std::to_string(codec::kMaxLookNameBytes) + " bytes); nothing sent");
    codec::Command command;
    command.request_id = ++command_serial_;
    command.kind = codec::Command::Kind::play_look;
    command.sentence = name;
    return send_message(command);
  }
  codec::Chat chat;
  chat.text = text;
  send_message(chat);
}

void RoomSession::say(const std::string& text) {
  if (greeted_) chat(text);
  else options_.say.push_back(text);
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
