#include "room.hpp"

#include <cmath>

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "monotonic_clock.hpp"
#include "peer_address.hpp"
#include "room_bus.hpp"
#include "room_registry.hpp"
#include "server_keys.hpp"
#include "visible_text.hpp"

namespace fw::server {

namespace net = boost::asio;

namespace {

/// `text` cut to at most `max` bytes without splitting a UTF-8 sequence.
std::string clip_utf8(std::string text, std::size_t max) {
  if (text.size() <= max) return text;
  std::size_t end = max;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  text.resize(end);
  return text;
}

RoomSimulationOptions simulation_options(const ServerConfig& config, std::uint64_t seed) {
  RoomSimulationOptions options{seed, config.tick_hz, config.physics, config.physics_sleeps};
  options.id_space = config.avatar_id_space;
  // Ticks never run ahead of the clock, so this many of them last at least as long.
  options.id_quiet_ticks =
      static_cast<std::uint64_t>((config.avatar_id_quiet.count() * config.tick_hz + 999) / 1000);
  return options;
}

/// "3 s": a wait as a person reads it, rounded up.
std::string whole_seconds(double seconds) { return std::to_string(static_cast<long>(std::ceil(seconds))) + " s"; }

AvatarCommand to_simulation(const codec::Command& c) {
  const double seconds = c.duration_ms / 1000.0;
  switch (c.kind) {
    case codec::Command::Kind::express: return ExpressCommand{c.emotion, c.intensity, seconds};
    case codec::Command::Kind::look_at: return LookAtCommand{c.target, seconds};
    case codec::Command::Kind::snub: return SnubCommand{c.target, seconds};
    case codec::Command::Kind::facs: break;
  }
  return FacsCommand{c.sentence};
}

}  // namespace

Room::Room(ServerContext& context, std::string name, bool persistent, std::uint64_t seed, RoomRole role)
    : context_(context), name_(std::move(name)), persistent_(persistent), strand_(net::make_strand(*context.workers)),
      timer_(strand_), simulation_(simulation_options(context.config, seed)), role_(role),
      chat_rate_(context.config.abuse.room_chat, TokenBucket::Clock::now()),
      join_rate_(context.config.abuse.room_joins, TokenBucket::Clock::now()) {
  context_.metrics.rooms.fetch_add(1);
}

Room::~Room() {
  context_.metrics.rooms.fetch_sub(1);
  context_.metrics.kinematic_faces.fetch_sub(static_cast<std::int64_t>(kinematic_faces_));
  context_.metrics.avatars.fetch_sub(static_cast<std::int64_t>(avatar_count_.load()));
}

void Room::start() {
  net::post(strand_, [self = shared_from_this()] {
    self->next_tick_ = std::chrono::steady_clock::now();
    self->schedule_tick();
  });
}

void Room::close() {
  net::post(strand_, [self = shared_from_this()] {
    self->closed_ = true;
    self->timer_.cancel();
    for (auto& [id, member] : self->members_)
      if (member.stream) member.stream->connection()->close(codec::CloseCode::shutting_down, "the room closed");
    self->members_.clear();
  });
}

void Room::then(std::function<void()> done) {
  net::post(strand_, [self = shared_from_this(), done = std::move(done)] { done(); });
}

void Room::join(JoinRequest request) {
  pending_joins_.fetch_add(1);
  net::post(strand_, [self = shared_from_this(), request = std::move(request)]() mutable {
    self->do_join(std::move(request));
  });
}

void Room::leave(std::uint32_t avatar) {
  net::post(strand_, [self = shared_from_this(), avatar] { self->do_leave(avatar); });
}

void Room::chat(std::uint32_t avatar, std::string text) {
  net::post(strand_, [self = shared_from_this(), avatar, text = std::move(text)]() mutable {
    self->do_chat(avatar, std::move(text));
  });
}

void Room::do_chat(std::uint32_t avatar, std::string text) {
  const auto it = members_.find(avatar);
  if (closed_ || it == members_.end()) return;
  if (role_ == RoomRole::bridge) {
    return context_.bus->send_up(name_, bridge::encode(bridge::up_chat(context_.bus->node(), avatar, std::move(text))));
  }
  Member& writer = it->second;
  // The owner cleans every line, its own people's and those bridged from
  // other nodes alike: what acts unseen is left out (visible_text.hpp), so
  // that every reader sees the line as it shows.
  std::string shown;
  clean_chat_text(text, shown, codec::kMaxChatBytes);
  if (shown.empty()) return;
  text = std::move(shown);
  if (!chat_rate_.take(TokenBucket::Clock::now())) {
    // The room's chat is at its rate (many writers, or one from many
    // addresses): the line is dropped and its writer told so, in place.
    // Nobody is thrown out for it: the others may be the ones chatting.
    const int per_minute = static_cast<int>(context_.config.abuse.room_chat.per_second * 60 + 0.5);
    const double wait = chat_rate_.seconds_until(TokenBucket::Clock::now());
    context_.abuse.note(Abuse::chat_rate, writer.address, "room '" + name_ + "' chats over its rate");
    notice(writer, "not sent: room '" + name_ + "' carries at most " + std::to_string(per_minute) +
                       " chat lines a minute; try again in " + whole_seconds(wait));
    return;
  }
  simulation_.chat(avatar, text);
  context_.metrics.chat_lines.fetch_add(1, std::memory_order_relaxed);
  const auto line = encode_shared(codec::Chat{avatar, text});
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_chat(line);
  if (context_.bus) {
    context_.bus->keep_chat(name_, *line);
    if (bridged_members() != 0) send_down(bridge::down_message(bridge::DownKind::chat, 0, *line));
  }
}

void Room::notice(Member& member, const std::string& text) {
  const auto line = encode_shared(codec::Chat{0, clip_utf8(text, codec::kMaxChatBytes)});
  if (member.stream) member.stream->post_chat(line);
  else if (!member.node.empty()) send_down(bridge::down_message(bridge::DownKind::chat, member.info.id, *line));
}

void Room::command(std::uint32_t avatar, codec::Command command) {
  net::post(strand_, [self = shared_from_this(), avatar, command = std::move(command)] {
    auto it = self->members_.find(avatar);
    if (self->closed_ || it == self->members_.end()) return;
    Member& member = it->second;
    if (self->role_ == RoomRole::bridge) {
      bridge::Bytes bytes;
      codec::write_message(command, bytes);
      return self->context_.bus->send_up(self->name_,
                                         bridge::encode(bridge::up_command(self->context_.bus->node(), avatar, bytes)));
    }
    if (!member.stream && member.node.empty()) return;
    std::string error = self->simulation_.command(avatar, to_simulation(command));
    const auto result =
        encode_shared(codec::CommandResult{command.request_id, clip_utf8(std::move(error), codec::kMaxReasonBytes)});
    if (member.stream) member.stream->post_result(result);
    else self->send_down(bridge::down_message(bridge::DownKind::result, avatar, *result));
  });
}

void Room::resync(std::uint32_t avatar, std::vector<std::uint32_t> avatars) {
  net::post(strand_, [self = shared_from_this(), avatar, avatars = std::move(avatars)] {
    auto it = self->members_.find(avatar);
    if (it != self->members_.end() && it->second.stream) it->second.stream->force_key_frames(avatars);
  });
}

void Room::set_rate(std::uint32_t avatar, std::uint32_t bps) {
  net::post(strand_, [self = shared_from_this(), avatar, bps] {
    auto it = self->members_.find(avatar);
    if (it == self->members_.end() || !it->second.stream) return;
    const auto& config = self->context_.config;
    it->second.stream->set_budget(std::min(bps == 0 ? config.default_client_bps : bps, config.max_client_bps));
  });
}

void Room::do_join(JoinRequest request) {
  pending_joins_.fetch_sub(1);
  if (closed_) return join_successor(std::move(request));
  if (role_ == RoomRole::bridge) return bridge_join(std::move(request));
  if (take_seat_back(request)) return;
  if (const auto refusal = refusal_of(request)) return refuse(request, refusal->first, refusal->second);
  const bool person = request.connection != nullptr || !request.node.empty();
  const std::uint32_t id = simulation_.add_avatar(AvatarSetup{request.name, person});
  if (id == 0) {
    context_.abuse.count_quietly(Abuse::room_full, 1);
    return refuse(request, codec::CloseCode::room_full, "room '" + name_ + "' is full; try another room");
  }
  Member member;
  member.address = request.address;
  member.node = request.node;
  member.order = next_order_++;
  member.resume_hash = request.connection ? resume_hash(request.resume) : request.resume_hash;
  member.info = {id, request.name, request.avatar.asset,
                 static_cast<std::uint32_t>(request.avatar.preview ? request.avatar.preview->size() : 0),
                 static_cast<std::uint32_t>(request.avatar.full ? request.avatar.full->size() : 0), person,
                 simulation_.seat(id)};
  member.avatar = request.avatar;
  const SharedBytes moved = reseat();
  // Counted before anyone hears of the joiner: whoever reads the counts
  // after a welcome or a presence message finds the joiner in them.
  if (person) person_count_.fetch_add(1);
  avatar_count_.fetch_add(1);
  context_.metrics.avatars.fetch_add(1);
  introduce_to_others(member);
  if (moved) broadcast_seats(moved);
  if (request.connection) {
    member.stream = welcome(member, request);
    local_persons_.fetch_add(1);
  }
  if (context_.bus) {
    keep(member);
    send_down(bridge::down_joined(request.join_ref, record_of(member)));
  }
  members_.emplace(id, std::move(member));
  // The joiner hears everyone's attention; the others hear the joiner's.
  const codec::Attention everyone = attention_now();
  codec::Attention joiner;
  for (const auto& entry : everyone.entries)
    if (entry.avatar == id) joiner.entries.push_back(entry);
  attention_sent_[id] = joiner.entries.front();
  broadcast_attention(joiner, id);
  if (request.connection) {
    Member& seated = members_.at(id);
    const auto bytes = encode_shared(everyone);
    seated.stream->charge(bytes->size());
    seated.stream->connection()->deliver(bytes);
  }
  context_.abuse.event(request.address.empty() ? std::string_view("-") : std::string_view(request.address),
                       "room '" + name_ + "': " + request.name + " joined as avatar " + std::to_string(id) +
                           (person ? " (person)" : " (autonomous)"));
}

void Room::join_successor(JoinRequest request) {
  // The room emptied and closed while this hello was on its way: seat the
  // joiner in its successor.
  if (!request.connection) return;
  if (auto room = context_.rooms->find_or_create(name_)) return room->join(std::move(request));
  if (context_.draining.load())
    request.connection->close(codec::CloseCode::shutting_down, "the server is shutting down; try again soon");
  else
    request.connection->close(codec::CloseCode::server_full, "the server holds its maximum number of rooms");
}

std::size_t Room::seats_of(const std::string& address) const {
  std::size_t seats = 0;
  for (const auto& [id, member] : members_) seats += member.person() && member.address == address;
  return seats;
}

std::size_t Room::seats_of_block(const std::string& block) const {
  std::size_t seats = 0;
  for (const auto& [id, member] : members_) seats += member.person() && address_group(member.address) == block;
  return seats;
}

std::optional<std::pair<codec::CloseCode, std::string>> Room::refusal_of(const JoinRequest& request) {
  const auto& config = context_.config;
  if (members_.size() >= config.room_size) {
    context_.abuse.count_quietly(Abuse::room_full, 1);
    return {{codec::CloseCode::room_full, "room '" + name_ + "' is full (" + std::to_string(config.room_size) +
                                              " avatars); try another room"}};
  }
  if ((request.connection || !request.node.empty()) && !request.address.empty()) {
    // One address cannot fill a room (the lobby least of all): the others
    // keep seats.
    const std::size_t share = config.abuse.seats_per_address != 0 ? config.abuse.seats_per_address
                                                                   : std::max<std::size_t>(1, config.room_size / 2);
    if (seats_of(request.address) >= share) {
      context_.abuse.note(Abuse::room_seats, request.address, "room '" + name_ + "' seats its share of them");
      return {{codec::CloseCode::room_full, "room '" + name_ + "' already seats " + std::to_string(share) +
                                                " people from your address, the most one address may hold; "
                                                "try another room"}};
    }
    // Nor can one network's addresses together.
    const std::size_t block_share = config.abuse.seats_per_block != 0
                                        ? config.abuse.seats_per_block
                                        : std::max<std::size_t>(1, config.room_size * 3 / 4);
    if (seats_of_block(address_group(request.address)) >= block_share) {
      context_.abuse.note(Abuse::room_seats, request.address, "room '" + name_ + "' seats its network's share");
      return {{codec::CloseCode::room_full, "room '" + name_ + "' already seats " + std::to_string(block_share) +
                                                " people from your network, the most one network may hold; "
                                                "try another room"}};
    }
  }
  // Joins into one room, from every address together: each join is news
  // to everyone in the room (a presence, a package), so churn from many
  // addresses must not bury the people there.
  if ((request.connection || !request.node.empty()) && !join_rate_.take(TokenBucket::Clock::now())) {
    const double wait = join_rate_.seconds_until(TokenBucket::Clock::now());
    context_.abuse.note(Abuse::join_rate, request.address, "room '" + name_ + "' takes joins over its rate");
    return {{codec::CloseCode::rate_limited,
             "room '" + name_ + "' takes no more joins this moment; try again in " + whole_seconds(wait)}};
  }
  if (!simulation_.has_free_id()) {
    context_.abuse.count_quietly(Abuse::room_full, 1);
    return {{codec::CloseCode::server_full,
             "room '" + name_ + "' has handed out all its avatar ids lately; try again in a minute"}};
  }
  return std::nullopt;
}

void Room::refuse(const JoinRequest& request, codec::CloseCode code, const std::string& why) {
  context_.metrics.rejected_joins.fetch_add(1);
  // Counted where the refusal was decided (refusal_of); logged with the rest.
  context_.abuse.event(request.address.empty() ? std::string_view("-") : std::string_view(request.address),
                       "room '" + name_ + "': " + request.name + " refused: " + why);
  if (request.connection) request.connection->close(code, why);
  else if (!request.node.empty())
    send_down(bridge::down_refused(request.join_ref, code, why));
  close_if_unpeopled();  // a room made for this join alone goes again
}

bool Room::unpeopled() const {
  return role_ == RoomRole::owner ? person_count_.load() == 0 : local_persons_.load() == 0;
}

void Room::close_if_unpeopled() {
  if (persistent_ || !unpeopled() || pending_joins_.load() != 0) return;
  if (role_ == RoomRole::bridge && (!held_joins_.empty() || !sent_joins_.empty())) return;
  if (context_.bus) context_.bus->room_closed(name_);
  context_.rooms->remove_if_empty(shared_from_this());
}

void Room::introduce_to_others(const Member& newcomer) {
  const auto joined = encode_shared(codec::Presence{codec::Presence::Change::joined, newcomer.info});
  for (auto& [other_id, other] : members_) {
    if (!other.stream) continue;
    other.stream->post_presence(codec::Presence::Change::joined, newcomer.info.id, joined);
    other.stream->add_avatar(newcomer.info.id, newcomer.avatar.preview, newcomer.avatar.full);
  }
}

std::unique_ptr<SubscriberStream> Room::welcome(const Member& newcomer, const JoinRequest& request) {
  codec::Welcome welcome;
  welcome.you = newcomer.info.id;
  welcome.resume = request.resume;
  welcome.room = name_;
  welcome.tick_hz = static_cast<std::uint8_t>(context_.config.tick_hz);
  welcome.max_bps = request.stream.budget_bps;
  // (A person taking a seat back is a member already: listed once, last.)
  for (const auto& [other_id, other] : members_)
    if (other_id != newcomer.info.id && welcome.avatars.size() + 1 < codec::kMaxWelcomeAvatars)
      welcome.avatars.push_back(other.info);
  welcome.avatars.push_back(newcomer.info);
  const auto welcome_bytes = encode_shared(welcome);
  request.connection->joined(newcomer.info.id, welcome_bytes);
  // The stream's header follows the welcome; then everyone's face.
  auto stream = std::make_unique<SubscriberStream>(request.stream, request.connection, context_.metrics);
  stream->charge(welcome_bytes->size());
  for (const auto& [other_id, other] : members_)
    if (other_id != newcomer.info.id) stream->add_avatar(other_id, other.avatar.preview, other.avatar.full);
  // A client that uploaded its package holds it: its own face costs its link nothing.
  if (request.stream.own_package) stream->add_avatar(newcomer.info.id, nullptr, nullptr);
  else stream->add_avatar(newcomer.info.id, newcomer.avatar.preview, newcomer.avatar.full);
  return stream;
}

void Room::do_leave(std::uint32_t avatar) {
  auto it = members_.find(avatar);
  if (it == members_.end()) return;
  if (role_ == RoomRole::bridge) {
    // The owner says who left; until then the seat is the owner's.
    if (it->second.stream) local_persons_.fetch_sub(1);
    it->second.stream.reset();
    it->second.local_gone = true;
    context_.bus->send_up(name_, bridge::encode(bridge::up_leave(context_.bus->node(), avatar)));
    return close_if_unpeopled();
  }
  const bool person = it->second.person();
  if (it->second.stream) local_persons_.fetch_sub(1);
  context_.abuse.event(it->second.address.empty() ? std::string_view("-") : std::string_view(it->second.address),
                       "room '" + name_ + "': " + it->second.info.name + " left");
  codec::AvatarInfo info;
  info.id = avatar;
  info.person = person;
  members_.erase(it);
  attention_sent_.erase(avatar);
  simulation_.remove_avatar(avatar);
  avatar_count_.fetch_sub(1);
  context_.metrics.avatars.fetch_sub(1);
  if (person) person_count_.fetch_sub(1);
  const auto left = encode_shared(codec::Presence{codec::Presence::Change::left, info});
  for (auto& [id, member] : members_) {
    if (!member.stream) continue;
    member.stream->remove_avatar(avatar);
    member.stream->post_presence(codec::Presence::Change::left, avatar, left);
  }
  if (context_.bus) {
    context_.bus->forget_member(name_, avatar);
    send_down(bridge::down_left(avatar));
  }
  if (const SharedBytes moved = reseat()) broadcast_seats(moved);
  close_if_unpeopled();
}

SharedBytes Room::reseat() {
  bool moved = false;
  codec::Seats seats;
  for (auto& [id, member] : members_) {
    const codec::SeatInfo seat = simulation_.seat(id);
    moved = moved || !(seat == member.info.seat);
    member.info.seat = seat;
    if (seats.seats.size() < codec::kMaxWelcomeAvatars) seats.seats.push_back({id, seat});
  }
  if (!moved) return nullptr;
  // The joiner, not yet a member, is in the layout too.
  for (const std::uint32_t id : simulation_.avatars())
    if (!members_.count(id) && seats.seats.size() < codec::kMaxWelcomeAvatars)
      seats.seats.push_back({id, simulation_.seat(id)});
  return encode_shared(seats);
}

codec::Attention Room::attention_now() const {
  codec::Attention attention;
  for (const auto& [id, member] : members_)
    if (attention.entries.size() < codec::kMaxWelcomeAvatars) attention.entries.push_back(simulation_.attention(id));
  return attention;
}

void Room::send_attention_changes() {
  codec::Attention changed;
  for (const auto& entry : attention_now().entries) {
    codec::Attention::Entry& sent = attention_sent_[entry.avatar];
    if (sent == entry) continue;
    sent = entry;
    changed.entries.push_back(entry);
  }
  if (!changed.entries.empty()) broadcast_attention(changed);
}

void Room::broadcast_seats(const SharedBytes& message) {
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_seats(message);
  // Every bridge keeps the room's seats and attention, people or not: it
  // welcomes its next joiner from them. (Only faces wait for bridged people.)
  if (role_ == RoomRole::owner && context_.bus)
    send_down(bridge::down_message(bridge::DownKind::seats, 0, *message));
}

void Room::broadcast_attention(const codec::Attention& attention, std::uint32_t except) {
  for (auto& [id, member] : members_)
    if (id != except && member.stream) member.stream->post_attention(attention);
  if (role_ == RoomRole::owner && context_.bus) {
    bridge::Bytes bytes;
    codec::write_message(attention, bytes);
    send_down(bridge::down_attention(std::move(bytes)));
  }
}

std::chrono::microseconds Room::tick_period() const {
  return std::chrono::microseconds(1'000'000 / context_.config.tick_hz);
}

void Room::schedule_tick() {
  const auto period = tick_period();
  next_tick_ += period;
  const auto now = std::chrono::steady_clock::now();
  if (next_tick_ < now - period) {
    // More than a tick behind (an overloaded pool): keep the pace from now
    // instead of running a burst of ticks to catch up.
    context_.metrics.late_ticks.fetch_add(1, std::memory_order_relaxed);
    next_tick_ = now;
  }
  timer_.expires_at(next_tick_);
  timer_.async_wait([self = shared_from_this()](const boost::system::error_code& ec) {
    if (ec || self->closed_) return;
    self->on_tick();
    self->schedule_tick();
  });
}

void Room::on_tick() {
  if (role_ == RoomRole::bridge) {
    if (++ticks_since_check_ >= static_cast<std::uint32_t>(context_.config.tick_hz) / 4) {
      ticks_since_check_ = 0;
      bridge_housekeeping();
    }
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  // How late this tick starts tells the governor whether the pool keeps up;
  // its answer is how many of this room's faces run physics (level of detail).
  context_.physics_lod.observe_tick(next_tick_, start, tick_period());
  simulation_.set_physics_share(context_.physics_lod.share());
  simulation_.tick();
  const std::size_t kinematic = simulation_.kinematic_faces();
  context_.metrics.kinematic_faces.fetch_add(static_cast<std::int64_t>(kinematic) -
                                             static_cast<std::int64_t>(kinematic_faces_));
  kinematic_faces_ = kinematic;
  for (const RoomEvent& event : simulation_.take_events())
    spdlog::debug("room {}: tick {} avatar {}: {}", name_, event.tick, event.avatar, event.what);
  faces_.clear();
  for (const auto& [id, member] : members_) faces_.push_back({id, &simulation_.face(id)});
  const std::uint64_t now_us = monotonic_us();
  const std::uint32_t tick = simulation_.tick_index();
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->tick(tick, now_us, faces_);
  if (context_.bus && bridged_members() != 0) {
    // Once per tick whatever the number of bridged people: each node encodes for its own.
    bridge::Down down = bridge::down_tick(tick);
    down.faces.reserve(faces_.size());
    for (const AvatarFace& face : faces_) down.faces.push_back({face.id, *face.face});
    send_down(down);
  }
  send_attention_changes();
  if (++ticks_since_check_ >= static_cast<std::uint32_t>(context_.config.tick_hz)) {
    ticks_since_check_ = 0;
    if (context_.bus) {
      keep_state();
      let_away_go();
    }
    close_if_unpeopled();
  }
  context_.metrics.observe_tick(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace fw::server
