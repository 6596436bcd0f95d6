#include "client_session.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "room_members.hpp"
#include "display_name.hpp"
#include "join_token.hpp"
#include "monotonic_clock.hpp"
#include "peer_address.hpp"
#include "room.hpp"
#include "room_registry.hpp"
#include "session_registry.hpp"
#include "server_keys.hpp"
#include "server_limits.hpp"
#include "speech_languages.hpp"

namespace fw::server {

namespace net = boost::asio;
using codec::CloseCode;
using codec::MessageError;

namespace {

/// "3 s": a wait as a person reads it, rounded up.
std::string wait_text(double seconds) { return std::to_string(static_cast<long>(std::ceil(seconds))) + " s"; }

}  // namespace

ClientSession::ClientSession(const SessionServices& services, net::any_io_executor executor, std::string peer)
    : services_(services), executor_(std::move(executor)), peer_(std::move(peer)), clock_(executor_),
      message_tokens_(limits::kMessageBurst), byte_tokens_(limits::kUpstreamByteBurst), chat_tokens_(limits::kChatBurst), script_tokens_(limits::kScriptBurst) {}

ClientSession::~ClientSession() {
  if (counted_) services_.metrics.connections.fetch_sub(1);
}

void ClientSession::start() {
  if (state_ == State::closed) return;  // it gave its place up before it started (give_up_place)
  services_.metrics.connections.fetch_add(1);
  counted_ = true;
  services_.sessions.add(shared_from_this());
  opened_ = last_heard_ = last_refill_ = last_sent_ = read_progress_ = std::chrono::steady_clock::now();
  on_clock();
  start_reading();
}

// --- sending --------------------------------------------------------------

void ClientSession::deliver(SharedBytes message) {
  queued_bytes_.fetch_add(message->size(), std::memory_order_relaxed);
  {
    const std::lock_guard lock(inbox_mutex_);
    inbox_.push_back(std::move(message));
    if (inbox_.size() > 1) return;  // the job that takes the first takes this one too
  }
  // In a room tick, one post for all its connections (delivery_batch.hpp).
  if (DeliveryBatch* batch = DeliveryBatch::open()) return batch->enlist(shared_from_this());
  net::post(executor_, [self = shared_from_this()] { self->take_inbox(); });
}

void ClientSession::take_inbox() {
  std::vector<SharedBytes> messages;
  {
    const std::lock_guard lock(inbox_mutex_);
    messages.swap(inbox_);
  }
  for (auto& message : messages) do_deliver(std::move(message));
}

void ClientSession::do_deliver(SharedBytes message) {
  if (state_ == State::closing || state_ == State::closed) {
    queued_bytes_.fetch_sub(message->size(), std::memory_order_relaxed);
    return;
  }
  if (queued_bytes_.load(std::memory_order_relaxed) > limits::kMaxQueuedBytes) {
    // Room frames and packages stop long before this; only a peer that
    // reads nothing while the room chats gets here. Its memory is bounded.
    queued_bytes_.fetch_sub(message->size(), std::memory_order_relaxed);
    services_.abuse.note(Abuse::not_reading, peer_, std::to_string(queued_bytes_.load()) + " bytes waiting; closed");
    state_ = State::closed;
    shutdown_transport(CloseCode::rate_limited, "the connection does not read what the server sends", true);
    return;
  }
  queue_.push_back(std::move(message));
  if (!writing_) write_next();
}

void ClientSession::write_next() {
  if (queue_.empty()) {
    writing_ = false;
    if (state_ == State::closing) {
      state_ = State::closed;
      shutdown_transport(close_code_, close_reason_, false);
    }
    return;
  }
  // From now on, bytes wait (where the socket can tell, the clock samples it instead).
  if (!writing_ && !socket_known_) read_progress_ = std::chrono::steady_clock::now();
  writing_ = true;
  start_write(queue_.front());
}

void ClientSession::on_write_done(bool ok, std::size_t bytes) {
  if (!queue_.empty()) {
    queued_bytes_.fetch_sub(queue_.front()->size(), std::memory_order_relaxed);
    queue_.pop_front();
  }
  if (!ok) {
    writing_ = false;
    on_transport_closed();
    return;
  }
  bytes_written_.fetch_add(bytes, std::memory_order_relaxed);
  services_.metrics.bytes_sent.fetch_add(bytes, std::memory_order_relaxed);
  // A write completes when the kernel takes the bytes, not the peer: where
  // the socket can tell, the clock samples it instead (sample_read_progress).
  if (!socket_known_) read_progress_ = std::chrono::steady_clock::now();
  write_next();
}

// --- closing --------------------------------------------------------------

void ClientSession::close(CloseCode code, std::string reason) {
  net::post(executor_, [self = shared_from_this(), code, reason = std::move(reason)]() mutable {
    // What the room delivered before closing is queued first, as when each
    // message was a post of its own (do_close drops what has not started).
    self->take_inbox();
    self->do_close(code, std::move(reason));
  });
}

void ClientSession::do_close(CloseCode code, std::string reason) {
  if (state_ == State::closing || state_ == State::closed) return;
  if (reason.size() > codec::kMaxReasonBytes) reason.resize(codec::kMaxReasonBytes);
  spdlog::debug("{}: closing ({}): {}", peer_, static_cast<int>(code), reason);
  // Whatever still waits is dropped: the closing message goes out next, alone.
  while (queue_.size() > (writing_ ? 1u : 0u)) {
    queued_bytes_.fetch_sub(queue_.back()->size(), std::memory_order_relaxed);
    queue_.pop_back();
  }
  const auto closing = encode_shared(codec::Closing{code, reason});
  queued_bytes_.fetch_add(closing->size(), std::memory_order_relaxed);
  queue_.push_back(closing);
  state_ = State::closing;
  close_code_ = code;
  close_reason_ = reason;
  closing_since_ = std::chrono::steady_clock::now();
  if (!writing_) write_next();
}

void ClientSession::give_up_place() {
  net::post(executor_, [self = shared_from_this()] {
    if (self->state_ == State::closing || self->state_ == State::closed) return;
    if (self->state_ != State::greeting)  // its hello came meanwhile: it is told why
      return self->do_close(CloseCode::server_full, "the server is full; connect again in a moment");
    // It said nothing, so it reads nothing: the socket goes at once, and
    // with it the descriptor the newcomer needs.
    self->state_ = State::closed;
    self->shutdown_transport(CloseCode::server_full, "the server is full", true);
  });
}

void ClientSession::on_transport_error(CloseCode code, const std::string& reason) {
  if (code == CloseCode::protocol_error || code == CloseCode::message_too_large)
    services_.metrics.protocol_errors.fetch_add(1);
  do_close(code, reason);
}

void ClientSession::on_transport_closed() {
  state_ = State::closed;
  if (transport_gone_) return;
  transport_gone_ = true;
  // A seat is given back here once taken; a hello still on its way to the
  // room keeps room_, so that joined() can give that seat back.
  if (room_ && seated_) {
    room_->leave(avatar_);
    room_.reset();
  }
  clock_.cancel();
  if (!held_token_.empty()) services_.tokens.release(held_token_, this);
  services_.sessions.remove(this);
}

void ClientSession::protocol_error(CloseCode code, const std::string& what, Abuse kind) {
  services_.abuse.note(kind, peer_, what);
  quick_close_ = true;
  on_transport_error(code, what);
}

// --- receiving ------------------------------------------------------------

bool ClientSession::take_token(double& tokens, double cost) {
  if (tokens < cost) return false;
  tokens -= cost;
  return true;
}

void ClientSession::note_received(std::size_t bytes) {
  services_.metrics.bytes_received.fetch_add(bytes, std::memory_order_relaxed);
}

bool ClientSession::note_control_frame(std::size_t bytes) {
  if (state_ == State::closing || state_ == State::closed) return false;
  refill_tokens(std::chrono::steady_clock::now());
  if (take_token(message_tokens_, 1) && take_token(byte_tokens_, static_cast<double>(bytes))) return true;
  services_.abuse.note(Abuse::message_rate, peer_, "WebSocket pings over the message rate");
  quick_close_ = true;
  on_transport_error(CloseCode::rate_limited, "too many messages (WebSocket pings count); at most 50 a second");
  return false;
}

void ClientSession::refill_tokens(std::chrono::steady_clock::time_point now) {
  const double elapsed = std::chrono::duration<double>(now - last_refill_).count();
  last_refill_ = now;
  message_tokens_ = std::min(limits::kMessageBurst, message_tokens_ + elapsed * limits::kMessagesPerSecond);
  byte_tokens_ = std::min(limits::kUpstreamByteBurst, byte_tokens_ + elapsed * limits::kUpstreamBytesPerSecond);
  chat_tokens_ = std::min(limits::kChatBurst, chat_tokens_ + elapsed * limits::kChatLinesPerSecond);
  script_tokens_ = std::min(limits::kScriptBurst, script_tokens_ + elapsed * limits::kScriptsPerSecond);
}

void ClientSession::on_message(std::span<const std::uint8_t> message) {
  if (state_ == State::closing || state_ == State::closed) return;
  // The transports stop larger messages while reading them; this holds for
  // any transport, the in-memory one included.
  if (message.size() > codec::kMaxUpstreamMessageBytes)
    return protocol_error(CloseCode::message_too_large, "a message over 8 KiB");
  last_heard_ = std::chrono::steady_clock::now();
  refill_tokens(last_heard_);
  if (!take_token(message_tokens_, 1) || !take_token(byte_tokens_, static_cast<double>(message.size())))
    return protocol_error(CloseCode::rate_limited, "too many messages; at most 50 a second and 64 KiB a second",
                          Abuse::message_rate);
  switch (state_) {
    case State::greeting:
      on_first_message();
      return handle_hello(message);
    case State::joining:
      if (early_messages_.size() >= limits::kMaxEarlyMessages)
        return protocol_error(CloseCode::rate_limited, "too many messages before the welcome; wait for it",
                              Abuse::message_rate);
      early_messages_.emplace_back(message.begin(), message.end());
      return;
    case State::joined: return handle_joined_message(message);
    default: return;
  }
}

void ClientSession::handle_hello(std::span<const std::uint8_t> message) {
  codec::Hello hello;
  const MessageError error = codec::read_message(message, hello);
  if (error == MessageError::unsupported_version)
    return protocol_error(CloseCode::unsupported_version,
                          "this server speaks protocol versions " + std::to_string(codec::kOldestProtocolVersion) +
                              " to " + std::to_string(codec::kProtocolVersion) + " only; update the client");
  if (error != MessageError::ok)
    return protocol_error(CloseCode::protocol_error,
                          "the first message must be a hello: " + std::string(codec::describe(error)));
  std::string name;
  if (const std::string why = normalize_display_name(hello.name, name); !why.empty())
    return refuse(CloseCode::bad_request, why, Abuse::bad_name);
  hello.name = std::move(name);
  if (const auto refusal = refusal_of(hello))
    return refuse(refusal->first, refusal->second,
                  refusal->first == CloseCode::unauthorized ? std::optional(Abuse::unauthorized) : std::nullopt);
  // Held by the address, so that leaving and joining again does not refill it.
  if (const auto wait = services_.addresses.take(AddressRate::join, address_key(peer_)))
    return refuse(CloseCode::rate_limited, "too many joins from your address; try again in " + wait_text(*wait),
                  Abuse::join_rate);
  if (hello.avatar.empty() && !hello.avatar_key.empty())
    return refuse(CloseCode::bad_request,
                  "an avatar key came without the avatar it opens: name the avatar the upload answered, or send "
                  "neither for a generated face");
  const AvatarLookup avatar = avatar_for(hello);
  switch (avatar.status) {
    case AvatarStatus::found: break;
    case AvatarStatus::unknown:
      return refuse(CloseCode::bad_request,
                    "unknown avatar '" + hello.avatar.substr(0, 64) + "'; upload it first (POST /api/avatars)");
    // Temporary: the client tries again (PROTOCOL.md, "closing").
    case AvatarStatus::being_prepared: return refuse(CloseCode::avatar_being_prepared, avatar.message);
    default: return refuse(CloseCode::bad_request, avatar.message);
  }
  if (!hello.avatar.empty() && !avatar_key_matches(services_.server_key, hello.avatar, hello.avatar_key))
    return refuse(CloseCode::unauthorized,
                  hello.avatar_key.empty()
                      ? "a face is worn with the key its upload answered (avatar_key); upload your photo to get yours"
                      : "that is not the key of this face: only who uploaded it may wear it",
                  Abuse::face_not_yours);
  if (!claim_token(hello)) return;
  preview_ = hello.preview;
  worn_asset_ = hello.avatar;  // its key matched above
  RoomOpening opening = preview_ ? services_.rooms.open_preview(address_key(peer_))
                                 : services_.rooms.open_for(hello.room, address_key(peer_));
  if (!opening.room) return refuse(opening.code, opening.refusal, opening.abuse);
  room_ = std::move(opening.room);
  state_ = State::joining;
  JoinRequest request{.name = hello.name,
                      .avatar = *avatar.avatar,
                      .stream = stream_settings_for(hello),
                      .connection = shared_from_this(),
                      .resume = resume_key_,
                      .address = address_key(peer_),
                      .returning = hello.resume,
                      .node = {},  // here: not bridged from another node
                      .join_ref = {},
                      .resume_hash = {},
                      .language = hello.language};  // checked by refusal_of; empty: the room's
  room_->join(std::move(request));
}

bool ClientSession::claim_token(const codec::Hello& hello) {
  if (services_.config.auth_secret.empty()) return true;
  const TokenClaim claim = services_.tokens.claim(hello.token, shared_from_this(), hello.resume, resume_key_);
  if (!claim.granted) {
    refuse(CloseCode::unauthorized,
           "this invitation is in use by someone connected now; each person needs their own (ask the host)",
           Abuse::token_in_use);
    return false;
  }
  held_token_ = hello.token;
  // The same person, back after a drop the server has not noticed yet:
  // the old connection gives way. Told why, it does not try again.
  if (claim.replaced) claim.replaced->close(CloseCode::unauthorized, "replaced by your newer connection");
  return true;
}

std::optional<std::pair<CloseCode, std::string>> ClientSession::refusal_of(const codec::Hello& hello) const {
  if (services_.draining.load()) return {{CloseCode::shutting_down, "the server is shutting down; try again soon"}};
  if (!is_valid_room_name(hello.room))
    return {{CloseCode::bad_request, "room names are 1 to 64 characters of A-Z a-z 0-9 _ - ."}};
  if (std::string why; chosen_language(hello.language, why).empty()) return {{CloseCode::bad_request, why}};
  if (services_.config.auth_secret.empty()) return std::nullopt;
  const auto now =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  std::string why = check_join_token(hello.token, services_.config.auth_secret, hello.room, hello.name, now);
  if (!why.empty()) return {{CloseCode::unauthorized, std::move(why)}};
  return std::nullopt;
}

AvatarLookup ClientSession::avatar_for(const codec::Hello& hello) const {
  if (!hello.avatar.empty()) return services_.store.lookup(hello.avatar);
  // No package: a procedural face, chosen by the name so it stays the same.
  return {AvatarStatus::found, procedural_face_for(services_.procedural_faces, hello.name), {}};
}

StreamSettings ClientSession::stream_settings_for(const codec::Hello& hello) const {
  const auto& config = services_.config;
  StreamSettings stream;
  stream.tick_hz = config.tick_hz;
  stream.budget_bps = std::min(hello.max_bps == 0 ? config.default_client_bps : hello.max_bps, config.max_client_bps);
  stream.timestamps = hello.timestamps;
  stream.packages = !hello.no_packages;
  stream.own_package = hello.own_package && !hello.avatar.empty();
  stream.protocol_version = hello.protocol_version;
  return stream;
}

namespace {

/// How a refused hello is counted when its refusal does not say.
Abuse refusal_kind(CloseCode code) {
  switch (code) {
    case CloseCode::shutting_down: return Abuse::shutting_down;
    case CloseCode::room_full:
    case CloseCode::server_full: return Abuse::room_full;
    case CloseCode::unauthorized: return Abuse::unauthorized;
    default: return Abuse::bad_hello;
  }
}

}  // namespace

void ClientSession::refuse(CloseCode code, const std::string& why, std::optional<Abuse> kind) {
  services_.metrics.rejected_joins.fetch_add(1);
  services_.abuse.note(kind.value_or(refusal_kind(code)), peer_, "hello refused: " + why);
  do_close(code, why);
}

void ClientSession::joined(std::uint32_t avatar, SharedBytes welcome) {
  queued_bytes_.fetch_add(welcome->size(), std::memory_order_relaxed);
  net::post(executor_, [self = shared_from_this(), avatar, welcome = std::move(welcome)]() mutable {
    // Dropped if the connection closed meanwhile.
    self->do_deliver(std::move(welcome));
    if (self->state_ != State::joining) {
      // Closed while the room seated us: give the seat back.
      if (self->room_) self->room_->leave(avatar);
      self->room_.reset();
      return;
    }
    self->seated_ = true;
    self->avatar_ = avatar;
    self->state_ = State::joined;
    auto early = std::move(self->early_messages_);
    for (const auto& message : early) self->handle_joined_message(message);
  });
}

void ClientSession::handle_joined_message(std::span<const std::uint8_t> message) {
  if (state_ != State::joined) return;
  // Pings keep a connection open, not a seat (on_clock: idle persons).
  if (codec::session_type(message) != codec::MessageType::ping) last_sent_ = std::chrono::steady_clock::now();
  switch (codec::classify(message)) {
    case codec::MessageKind::resync_request: return handle_resync(message);
    case codec::MessageKind::session: break;
    default:
      return protocol_error(CloseCode::protocol_error, "a message no client sends (first byte " +
                                                           std::to_string(message.empty() ? 0 : message[0]) + ")");
  }
  switch (codec::session_type(message)) {
    case codec::MessageType::chat: return handle_chat(message);
    case codec::MessageType::command: return handle_command(message);
    case codec::MessageType::set_rate: return handle_set_rate(message);
    case codec::MessageType::ping: return handle_ping(message);
    default:
      return protocol_error(CloseCode::protocol_error, "a message only the server sends, or a second hello");
  }
}

void ClientSession::malformed(MessageError error, const char* what) {
  protocol_error(error == MessageError::too_large ? CloseCode::message_too_large : CloseCode::protocol_error,
                 std::string("malformed ") + what + ": " + std::string(codec::describe(error)));
}

void ClientSession::handle_resync(std::span<const std::uint8_t> message) {
  std::vector<std::uint32_t> ids;
  if (const auto e = codec::read_resync_request(message, ids); e != codec::DecodeError::ok)
    return protocol_error(CloseCode::protocol_error, "malformed resync request: " + std::string(codec::describe(e)));
  room_->resync(avatar_, std::move(ids));
}

void ClientSession::handle_chat(std::span<const std::uint8_t> message) {
  codec::Chat chat;
  if (const auto e = codec::read_message(message, chat); e != MessageError::ok) return malformed(e, "chat");
  if (chat.text.empty()) return;
  if (!take_token(chat_tokens_, 1))
    return protocol_error(CloseCode::rate_limited, "too many chat lines; at most 2 a second", Abuse::chat_rate);
  // Over its address's rate (all its connections together; the room's rate
  // is the room's to check) the line is dropped, and its writer told so in
  // a line from the server, as a chat window shows a line that did not go.
  // The connection stays: whoever shares the address (a household, an
  // office behind one NAT) may be the one who chats, not this person.
  if (const auto wait = services_.addresses.take(AddressRate::chat, address_key(peer_))) {
    services_.abuse.note(Abuse::chat_rate, peer_, "chat over its address's rate");
    auto notice = encode_shared(codec::Chat{0, "not sent: too many chat lines from your address; try again in " +
                                                   wait_text(*wait)});
    queued_bytes_.fetch_add(notice->size(), std::memory_order_relaxed);  // as deliver() does
    return do_deliver(std::move(notice));
  }
  room_->chat(avatar_, std::move(chat.text));
}

void ClientSession::handle_command(std::span<const std::uint8_t> message) {
  codec::Command command;
  if (const auto e = codec::read_message(message, command); e != MessageError::ok) return malformed(e, "command");
  if (command.kind == codec::Command::Kind::facs || command.kind == codec::Command::Kind::play_look) {
    // A saved look is a script: it takes the script rate before it is read.
    if (auto refusal = script_refusal()) return answer_command(command.request_id, std::move(*refusal));
  }
  if (command.kind == codec::Command::Kind::play_look) return play_look(std::move(command));
  room_->command(avatar_, std::move(command));
}

void ClientSession::answer_command(std::uint32_t request_id, std::string error) {
  auto result = encode_shared(codec::CommandResult{request_id, std::move(error)});
  queued_bytes_.fetch_add(result->size(), std::memory_order_relaxed);  // as deliver() does
  do_deliver(std::move(result));
}

void ClientSession::play_look(codec::Command command) {
  if (worn_asset_.empty())
    return answer_command(command.request_id,
                          "saved looks are kept with an uploaded avatar: join wearing yours (with its key) to play "
                          "them");
  net::post(services_.workers, [self = shared_from_this(), command = std::move(command)]() mutable {
    std::optional<SavedLook> look = self->services_.looks.find(self->worn_asset_, command.sentence);
    net::post(self->executor_, [self, command = std::move(command), look = std::move(look)]() mutable {
      if (self->state_ != State::joined) return;
      if (!look)
        return self->answer_command(
            command.request_id, "your avatar has no look named '" + command.sentence.substr(0, 32) +
                                    "': save it first (face lab, Save), or pick one of yours");
      command.kind = codec::Command::Kind::facs;
      command.sentence = std::move(look->script);
      self->room_->command(self->avatar_, std::move(command));
    });
  });
}

// A script over the connection's or its address's rate is refused with a
// command result, not a closing: a typo's retries are no flood, and the
// address may be shared (a household, an office behind one NAT). The
// message rate (50 a second) still closes a real flood.
std::optional<std::string> ClientSession::script_refusal() {
  if (script_tokens_ < 1) {
    services_.abuse.note(Abuse::script_rate, peer_, "face scripts over the connection's rate");
    return "too many scripts; at most " + std::to_string(static_cast<int>(limits::kScriptsPerSecond)) +
           " a second: try again in " + wait_text((1 - script_tokens_) / limits::kScriptsPerSecond);
  }
  if (const auto wait = services_.addresses.take(AddressRate::script, address_key(peer_))) {
    services_.abuse.note(Abuse::script_rate, peer_, "face scripts over its address's rate");
    return "too many scripts from your address; try again in " + wait_text(*wait);
  }
  script_tokens_ -= 1;
  return std::nullopt;
}

void ClientSession::handle_set_rate(std::span<const std::uint8_t> message) {
  codec::SetRate rate;
  if (const auto e = codec::read_message(message, rate); e != MessageError::ok) return malformed(e, "set rate");
  room_->set_rate(avatar_, rate.max_bps);
}

void ClientSession::handle_ping(std::span<const std::uint8_t> message) {
  codec::Ping ping;
  if (const auto e = codec::read_message(message, ping); e != MessageError::ok) return malformed(e, "ping");
  auto pong = encode_shared(codec::Pong{ping.nonce, ping.client_time_us, monotonic_us()});
  queued_bytes_.fetch_add(pong->size(), std::memory_order_relaxed);  // as deliver() does
  do_deliver(std::move(pong));
}

// --- the clock: time-outs ---------------------------------------------------

namespace {

/// "5 s", "0.25 s": a time-out as a person reads it.
std::string seconds_text(std::chrono::milliseconds time) {
  std::ostringstream text;
  text << static_cast<double>(time.count()) / 1000.0 << " s";
  return text.str();
}

}  // namespace

std::chrono::milliseconds ClientSession::clock_period() const {
  // A quarter of the shortest time-out, so that each is kept within a
  // quarter of itself; never more often than every 10 ms.
  const auto& t = services_.config.timeouts;
  const auto shortest = std::min({t.handshake, t.idle, t.close, t.idle_person});
  return std::clamp<std::chrono::milliseconds>(shortest / 4, std::chrono::milliseconds(10), std::chrono::seconds(1));
}

void ClientSession::sample_read_progress(std::chrono::steady_clock::time_point now) {
  const auto queue = socket_queue();
  if (!queue) return;
  socket_known_ = true;
  const std::size_t held = queue->unacknowledged;
  const std::uint64_t written = bytes_written_.load(std::memory_order_relaxed);
  const std::uint64_t could_hold = socket_queue_ + (written - written_at_sample_);
  const bool room_for_it = queue->peer_window ? *queue->peer_window >= held : held < could_hold;
  if (held == 0 || room_for_it) read_progress_ = now;
  socket_queue_ = held;
  written_at_sample_ = written;
}

void ClientSession::on_clock() {
  const auto now = std::chrono::steady_clock::now();
  const auto& timeouts = services_.config.timeouts;
  if (state_ == State::joined) sample_read_progress(now);
  if (state_ == State::greeting && now - opened_ > timeouts.handshake) {
    services_.metrics.rejected_joins.fetch_add(1);
    services_.abuse.note(Abuse::handshake_timeout, peer_, "no hello within " + seconds_text(timeouts.handshake));
    quick_close_ = true;
    do_close(CloseCode::handshake_timeout, "no hello within " + seconds_text(timeouts.handshake) + " of connecting");
  } else if (state_ == State::joined && now - last_heard_ > timeouts.idle) {
    services_.abuse.note(Abuse::idle_timeout, peer_, "nothing heard for " + seconds_text(timeouts.idle));
    quick_close_ = true;
    do_close(CloseCode::idle_timeout,
             "nothing heard for " + seconds_text(timeouts.idle) + "; send a ping at least every " +
                 seconds_text(timeouts.idle / 3));
  } else if (state_ == State::joined && preview_ && now - last_sent_ > services_.config.previews.idle) {
    // A lab left open in a forgotten tab holds a room's tick for nothing.
    quick_close_ = true;
    do_close(CloseCode::idle_timeout, "the face-lab preview ended: nothing changed for " +
                                          seconds_text(services_.config.previews.idle) + "; reload the page to go on");
  } else if (state_ == State::joined && now - last_sent_ > timeouts.idle_person && (writing_ || socket_queue_ > 0) &&
             now - read_progress_ > timeouts.idle_person) {
    // Nothing but pings came, and what waits for the person is not taken
    // (in our queue, or in the socket past what the peer's buffer holds):
    // nobody is there, or someone holds a seat, and a room, for nothing. A
    // quiet viewer reads, so stays.
    services_.abuse.note(Abuse::idle_person, peer_, "neither sent nor read; let go");
    quick_close_ = true;
    do_close(CloseCode::idle_timeout, "let go: you neither sent nor read anything for " +
                                          seconds_text(timeouts.idle_person) + "; the seat is for someone who is here");
  } else if (state_ == State::closing && now - closing_since_ > timeouts.close) {
    state_ = State::closed;  // the peer does not take the closing message
    shutdown_transport(close_code_, close_reason_, true);
  }
  if (state_ == State::closed && !writing_) return;
  // The hello's deadline is kept to the millisecond (PROTOCOL.md 7 promises
  // it), not to a quarter of the shortest time-out.
  auto next = std::chrono::duration_cast<std::chrono::steady_clock::duration>(clock_period());
  if (state_ == State::greeting)
    next = std::clamp<std::chrono::steady_clock::duration>(opened_ + timeouts.handshake - now + std::chrono::milliseconds(1),
                                                           std::chrono::milliseconds(1), next);
  clock_.expires_after(next);
  clock_.async_wait([weak = weak_from_this()](const boost::system::error_code& ec) {
    if (ec) return;
    if (auto self = weak.lock()) self->on_clock();
  });
}

}  // namespace fw::server
