#include "room_session.hpp"

#include <algorithm>

#include <boost/asio/post.hpp>

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

constexpr auto kPingInterval = std::chrono::seconds(2);
constexpr auto kResyncInterval = std::chrono::milliseconds(500);
constexpr auto kHousekeeping = std::chrono::milliseconds(250);

}  // namespace

RoomSession::RoomSession(asio::io_context& io, SessionOptions options, RoomState& state)
    : io_(io), options_(std::move(options)), state_(state), reconnect_timer_(io), housekeeping_timer_(io) {}

RoomSession::~RoomSession() = default;

std::chrono::milliseconds RoomSession::backoff(int failed_attempts) {
  const int doublings = std::clamp(failed_attempts - 1, 0, 4);
  return std::chrono::milliseconds(500 << doublings);
}

void RoomSession::start() {
  connect();
  tick_timers();
}

void RoomSession::stop() {
  stopped_ = true;
  ++connection_serial_;
  reconnect_timer_.cancel();
  housekeeping_timer_.cancel();
  if (channel_) channel_->close();
}

void RoomSession::event(const std::string& text) {
  if (options_.on_event) options_.on_event(text);
}

std::uint64_t RoomSession::now_us() const {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch()).count());
}

void RoomSession::connect() {
  if (stopped_) return;
  channel_ = MessageChannel::make(io_, options_.url);
  const std::uint64_t serial = ++connection_serial_;
  channel_->connect(kConnectTimeoutS, [this, serial](boost::system::error_code ec) {
    if (serial != connection_serial_ || stopped_) return;
    on_connected(ec);
  });
}

void RoomSession::on_connected(boost::system::error_code ec) {
  if (ec) return connection_lost("cannot connect: " + ec.message());
  {
    std::lock_guard lock(state_.mutex);
    state_.joined = false;
    state_.decoder = codec::RoomDecoder();
  }
  packages_.clear();
  clock_offset_us_.reset();
  best_round_trip_us_ = UINT64_MAX;
  outbox_.clear();
  writing_ = false;
  codec::Hello hello;
  hello.room = options_.room;
  hello.name = options_.name;
  hello.avatar = options_.avatar_asset;
  hello.token = options_.token;
  hello.max_bps = options_.max_bps;
  hello.timestamps = options_.timestamps;
  hello.own_package = options_.own_package != nullptr;
  std::vector<std::uint8_t> bytes;
  codec::write_message(hello, bytes);
  send(std::move(bytes));
  read();
}

void RoomSession::read() {
  const std::uint64_t serial = connection_serial_;
  channel_->read([this, serial](boost::system::error_code ec, std::span<const std::uint8_t> message) {
    if (serial != connection_serial_ || stopped_) return;
    if (ec) return connection_lost(ec == asio::error::eof ? "the server closed the connection" : ec.message());
    {
      std::lock_guard lock(state_.mutex);
      state_.stats.bytes_down(message.size() + channel_->framing_bytes(message.size(), false));
    }
    on_message(message);
    if (serial == connection_serial_ && !stopped_) read();
  });
}

void RoomSession::on_message(std::span<const std::uint8_t> message) {
  switch (codec::classify(message)) {
    case codec::MessageKind::session:
      return on_session_message(message);
    case codec::MessageKind::stream_header: {
      codec::StreamOptions stream;
      const codec::DecodeError error = codec::read_stream_header(message, stream);
      if (error != codec::DecodeError::ok)
        return connection_lost("bad stream header from the server: " + std::string(codec::describe(error)));
      std::lock_guard lock(state_.mutex);
      state_.decoder = codec::RoomDecoder(stream);
      return;
    }
    case codec::MessageKind::room_frame:
      return on_room_frame(message, nullptr);
    case codec::MessageKind::resync_request:
    case codec::MessageKind::invalid:
      return connection_lost("the server sent a message a client does not expect (first byte " +
                             std::to_string(message.empty() ? -1 : message[0]) + ")");
  }
}

void RoomSession::on_session_message(std::span<const std::uint8_t> message) {
  const codec::MessageType type = codec::session_type(message);
  codec::MessageError error = codec::MessageError::ok;
  switch (type) {
    case codec::MessageType::welcome: {
      codec::Welcome welcome;
      if ((error = codec::read_message(message, welcome)) == codec::MessageError::ok) on_welcome(welcome);
      break;
    }
    case codec::MessageType::presence: {
      codec::Presence presence;
      if ((error = codec::read_message(message, presence)) != codec::MessageError::ok) break;
      std::lock_guard lock(state_.mutex);
      const std::uint32_t id = presence.avatar.id;
      if (presence.change == codec::Presence::Change::joined) {
        state_.avatars[id].info = presence.avatar;
        state_.record({"joined", presence.avatar.name, ""});
        event(presence.avatar.name + " joined");
      } else {
        const std::string name = state_.name_of(id);
        state_.avatars.erase(id);
        state_.decoder.remove(id);
        packages_.forget(id);
        state_.record({"left", name, ""});
        event(name + " left");
      }
      break;
    }
    case codec::MessageType::chat: {
      codec::Chat chat;
      if ((error = codec::read_message(message, chat)) != codec::MessageError::ok) break;
      std::lock_guard lock(state_.mutex);
      const std::string name = state_.name_of(chat.from);
      state_.record({"chat", name, chat.text});
      event(name + ": " + chat.text);
      break;
    }
    case codec::MessageType::command_result: {
      codec::CommandResult result;
      if ((error = codec::read_message(message, result)) != codec::MessageError::ok) break;
      if (!result.error.empty()) event("command refused: " + result.error);
      break;
    }
    case codec::MessageType::package_chunk: {
      codec::PackageChunk chunk;
      if ((error = codec::read_message(message, chunk)) != codec::MessageError::ok) break;
      std::string problem;
      auto package = packages_.add(chunk, problem);
      if (!problem.empty()) event(problem);
      if (!package) break;
      std::lock_guard lock(state_.mutex);
      const auto it = state_.avatars.find(package->avatar);
      if (it == state_.avatars.end()) break;
      RoomAvatar& avatar = it->second;
      // A late preview never replaces the full package.
      if (avatar.package_quality == codec::PackageChunk::Quality::full &&
          package->quality == codec::PackageChunk::Quality::preview)
        break;
      state_.stats.package(package->avatar, package->quality == codec::PackageChunk::Quality::full, Clock::now());
      avatar.package = std::make_shared<const std::vector<std::uint8_t>>(std::move(package->bytes));
      avatar.package_quality = package->quality;
      ++avatar.package_serial;
      break;
    }
    case codec::MessageType::pong: {
      codec::Pong pong;
      if ((error = codec::read_message(message, pong)) != codec::MessageError::ok) break;
      const std::uint64_t now = now_us();
      if (pong.client_time_us > now) break;
      const std::uint64_t round_trip = now - pong.client_time_us;
      // The server stamped the pong about half a round trip after the ping left.
      if (round_trip <= best_round_trip_us_) {
        best_round_trip_us_ = round_trip;
        clock_offset_us_ = static_cast<std::int64_t>(pong.server_time_us) -
                           static_cast<std::int64_t>(pong.client_time_us + round_trip / 2);
      }
      break;
    }
    case codec::MessageType::link_stats: {
      codec::LinkStats link;
      if ((error = codec::read_message(message, link)) != codec::MessageError::ok) break;
      std::lock_guard lock(state_.mutex);
      state_.server_link = link;
      break;
    }
    case codec::MessageType::closing: {
      codec::Closing closing;
      if ((error = codec::read_message(message, closing)) == codec::MessageError::ok) on_closing(closing);
      break;
    }
    case codec::MessageType::timed_room_frame: {
      codec::TimedRoomFrame timed;
      if ((error = codec::read_message(message, timed)) == codec::MessageError::ok) on_room_frame(timed.room_frame, &timed);
      break;
    }
    default:
      error = codec::MessageError::wrong_type;  // an upstream message coming down
      break;
  }
  if (error != codec::MessageError::ok)
    connection_lost("malformed message from the server (type " + std::to_string(static_cast<int>(type)) +
                    "): " + std::string(codec::describe(error)));
}

void RoomSession::on_welcome(const codec::Welcome& welcome) {
  {
    std::lock_guard lock(state_.mutex);
    if (greeted_) state_.stats.reconnected();  // a welcome before this one: the link came back
    state_.stats.joined(Clock::now());
    state_.joined = true;
    state_.you = welcome.you;
    state_.room = welcome.room;
    state_.tick_hz = std::max<int>(1, welcome.tick_hz);
    // Keep the packages of avatars still here under the same asset: the
    // server sends them again, but the face need not wait for them.
    std::map<std::uint32_t, RoomAvatar> avatars;
    for (const codec::AvatarInfo& info : welcome.avatars) {
      RoomAvatar& avatar = avatars[info.id];
      const auto old = state_.avatars.find(info.id);
      if (old != state_.avatars.end() && old->second.info.asset == info.asset && !info.asset.empty()) avatar = old->second;
      avatar.info = info;
    }
    state_.avatars = std::move(avatars);
    // The own face: the package this client uploaded, there before any
    // chunk could be (the server sends none of it back).
    const auto own = state_.avatars.find(welcome.you);
    if (options_.own_package && own != state_.avatars.end() && !own->second.package) {
      own->second.package = options_.own_package;
      own->second.package_quality = codec::PackageChunk::Quality::full;
      ++own->second.package_serial;
      state_.stats.package(welcome.you, true, Clock::now());
    }
  }
  failed_attempts_ = 0;
  event("joined room " + welcome.room + " as avatar " + std::to_string(welcome.you) + " with " +
        std::to_string(welcome.avatars.size()) + " avatar(s) present");
  if (greeted_) return;
  greeted_ = true;
  for (const std::string& line : options_.say) chat(line);
  if (!options_.emote.empty()) {
    codec::Command command;
    command.request_id = ++command_serial_;
    command.kind = codec::Command::Kind::express;
    command.emotion = options_.emote;
    command.intensity = 1.0f;
    command.duration_ms = 3000;
    std::vector<std::uint8_t> bytes;
    codec::write_message(command, bytes);
    send(std::move(bytes));
  }
}

void RoomSession::chat(const std::string& text) {
  codec::Chat chat;
  chat.text = text;
  std::vector<std::uint8_t> bytes;
  codec::write_message(chat, bytes);
  send(std::move(bytes));
}

void RoomSession::on_closing(const codec::Closing& closing) {
  const std::string reason = closing.reason.empty() ? "no reason given" : closing.reason;
  if (refused_for_good(closing.code)) {
    {
      std::lock_guard lock(state_.mutex);
      state_.fatal_error = "the server refused this client: " + reason + " (closing code " +
                           std::to_string(static_cast<int>(closing.code)) + ")";
    }
    event("server: " + reason);
    stop();
    return;
  }
  connection_lost("the server closed the connection: " + reason);
}

void RoomSession::on_room_frame(std::span<const std::uint8_t> room_frame, const codec::TimedRoomFrame* timing) {
  const auto now = Clock::now();
  std::lock_guard lock(state_.mutex);
  const codec::RoomDecoder::Result result = state_.decoder.decode(room_frame);
  if (result.error != codec::DecodeError::ok) {
    state_.stats.decode_error();
    return;
  }
  bool any = false;
  for (const auto& [id, error] : result.avatars) {
    if (error != codec::DecodeError::ok) {
      state_.stats.decode_error();
      continue;
    }
    any = true;
    state_.stats.frame(id, state_.name_of(id));
    const auto it = state_.avatars.find(id);
    if (it != state_.avatars.end()) it->second.last_frame_at = now;
  }
  if (any && timing && clock_offset_us_) {
    const double client_tick_us = static_cast<double>(timing->server_time_us) - static_cast<double>(*clock_offset_us_);
    state_.stats.latency_ms(std::max(0.0, (static_cast<double>(now_us()) - client_tick_us) / 1000.0));
  }
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
  if (writing_ || outbox_.empty() || !channel_) return;
  writing_ = true;
  const std::uint64_t serial = connection_serial_;
  const auto message = outbox_.front();
  channel_->write(message, [this, serial, message](boost::system::error_code ec) {
    if (serial != connection_serial_ || stopped_) return;
    writing_ = false;
    if (ec) return connection_lost("sending failed: " + ec.message());
    {
      std::lock_guard lock(state_.mutex);
      state_.stats.bytes_up(message->size() + channel_->framing_bytes(message->size(), true));
    }
    outbox_.pop_front();
    write_next();
  });
}

void RoomSession::tick_timers() {
  if (stopped_) return;
  housekeeping_timer_.expires_after(kHousekeeping);
  housekeeping_timer_.async_wait([this](boost::system::error_code ec) {
    if (ec || stopped_) return;
    std::vector<std::uint32_t> need_keys;
    bool joined;
    {
      std::lock_guard lock(state_.mutex);
      joined = state_.joined;
      if (joined) need_keys = state_.decoder.needing_key_frames();
    }
    const auto now = Clock::now();
    if (joined && now - last_ping_ >= kPingInterval) {
      last_ping_ = now;
      codec::Ping ping{++ping_nonce_, now_us()};
      std::vector<std::uint8_t> bytes;
      codec::write_message(ping, bytes);
      send(std::move(bytes));
    }
    if (joined && !need_keys.empty() && now - last_resync_ >= kResyncInterval) {
      last_resync_ = now;
      if (need_keys.size() > codec::kMaxRoomAvatars) need_keys.resize(codec::kMaxRoomAvatars);
      std::vector<std::uint8_t> bytes;
      codec::write_resync_request(need_keys, bytes);
      send(std::move(bytes));
    }
    tick_timers();
  });
}

void RoomSession::connection_lost(const std::string& why) {
  if (stopped_) return;
  ++connection_serial_;
  if (channel_) channel_->close();
  writing_ = false;
  outbox_.clear();
  {
    std::lock_guard lock(state_.mutex);
    state_.joined = false;
  }
  ++failed_attempts_;
  const auto wait = backoff(failed_attempts_);
  event(why + "; reconnecting in " + std::to_string(wait.count()) + " ms");
  reconnect_timer_.expires_after(wait);
  reconnect_timer_.async_wait([this](boost::system::error_code ec) {
    if (!ec) connect();
  });
}

}  // namespace fw::client
