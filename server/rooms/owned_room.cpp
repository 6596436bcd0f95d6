#include "owned_room.hpp"

#include <algorithm>
#include <cmath>

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "face_stepper.hpp"
#include "monotonic_clock.hpp"
#include "peer_address.hpp"
#include "server_keys.hpp"
#include "visible_text.hpp"

namespace fw::server {

namespace {

/// `text` cut to at most `max` bytes without splitting a UTF-8 sequence.
std::string clip_utf8(std::string text, std::size_t max) {
  if (text.size() <= max) return text;
  std::size_t end = max;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  text.resize(end);
  return text;
}

/// "3 s": a wait as a person reads it, rounded up.
std::string whole_seconds(double seconds) { return std::to_string(static_cast<long>(std::ceil(seconds))) + " s"; }

AvatarCommand to_simulation(const codec::Command& c) {
  const double seconds = c.duration_ms / 1000.0;
  switch (c.kind) {
    case codec::Command::Kind::express: return ExpressCommand{c.emotion, c.intensity, seconds};
    case codec::Command::Kind::look_at: return LookAtCommand{c.target, seconds};
    case codec::Command::Kind::snub: return SnubCommand{c.target, seconds};
    case codec::Command::Kind::override_face: return OverrideCommand{c.override_face};
    case codec::Command::Kind::check: return CheckCommand{c.sentence};
    case codec::Command::Kind::facs:
    // Never here: the session that took it sends the look's script as a
    // FACS command (client_session.cpp); OwnedRoom::command refuses it.
    case codec::Command::Kind::play_look: break;
  }
  return FacsCommand{c.sentence};
}

}  // namespace

OwnedRoom::OwnedRoom(Room& room)
    : room_(room), services_(room.services()), name_(room.name()), simulation_(room.simulation()),
      counts_(room.counts()), chat_rate_(services_.config.abuse.room_chat, TokenBucket::Clock::now()),
      join_rate_(services_.config.abuse.room_joins, TokenBucket::Clock::now()) {}

void OwnedRoom::close() { close_every_member(members_); }

RoomHandover OwnedRoom::hand_over() {
  RoomHandover handover;
  for (auto& [id, member] : members_) handover.members.emplace(id, std::move(static_cast<Member&>(member)));
  members_.clear();
  return handover;
}

void OwnedRoom::chat(std::uint32_t avatar, std::string text) {
  const auto it = members_.find(avatar);
  if (it == members_.end()) return;
  OwnedMember& writer = it->second;
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
    const int per_minute = static_cast<int>(services_.config.abuse.room_chat.per_second * 60 + 0.5);
    const double wait = chat_rate_.seconds_until(TokenBucket::Clock::now());
    services_.abuse.note(Abuse::chat_rate, writer.address, "room '" + name_ + "' chats over its rate");
    notice(writer, "not sent: room '" + name_ + "' carries at most " + std::to_string(per_minute) +
                       " chat lines a minute; try again in " + whole_seconds(wait));
    return;
  }
  simulation_.chat(avatar, text);
  services_.metrics.chat_lines.fetch_add(1, std::memory_order_relaxed);
  const auto line = encode_shared(codec::Chat{avatar, text});
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_chat(line);
  services_.bus.keep_chat(name_, *line);
  if (bridged_members() != 0) send_down(bridge::down_message(bridge::DownKind::chat, 0, *line));
}

void OwnedRoom::notice(OwnedMember& member, const std::string& text) {
  const auto line = encode_shared(codec::Chat{0, clip_utf8(text, codec::kMaxChatBytes)});
  if (member.stream) member.stream->post_chat(line);
  else if (!member.node.empty()) send_down(bridge::down_message(bridge::DownKind::chat, member.info.id, *line));
}

void OwnedRoom::command(std::uint32_t avatar, const codec::Command& command) {
  auto it = members_.find(avatar);
  if (it == members_.end()) return;
  OwnedMember& member = it->second;
  if (!member.stream && member.node.empty()) return;
  const auto before = simulation_.unit_morphs(avatar);
  std::string error = command.kind == codec::Command::Kind::play_look
                          ? "a saved look is played through the connection that names it"
                          : simulation_.command(avatar, to_simulation(command));
  const auto after = simulation_.unit_morphs(avatar);
  if (after && (!before || before->version != after->version)) broadcast_unit_morphs(avatar);
  const auto result =
      encode_shared(codec::CommandResult{command.request_id, clip_utf8(std::move(error), codec::kMaxReasonBytes)});
  if (member.stream) member.stream->post_result(result);
  else send_down(bridge::down_message(bridge::DownKind::result, avatar, *result));
}

void OwnedRoom::resync(std::uint32_t avatar, const std::vector<std::uint32_t>& avatars) {
  resync_member(members_, avatar, avatars);
}

void OwnedRoom::set_rate(std::uint32_t avatar, std::uint32_t bps) {
  set_member_budget(members_, avatar, bps, services_.config.default_client_bps, services_.config.max_client_bps);
}

void OwnedRoom::replace_deleted_avatar(const std::string& asset) {
  // Whoever takes the room over, or welcomes a newcomer on another node, names the new face.
  replace_deleted_face(members_, asset, services_.procedural_faces, name_, [this](const OwnedMember& member) {
    keep(member);
    give_own_face(member.info.id, member.avatar);
  });
}

void OwnedRoom::join(JoinRequest request) {
  if (take_seat_back(request)) return;
  if (const auto refusal = refusal_of(request)) return refuse(request, refusal->first, refusal->second);
  request.avatar = unworn_procedural_face(members_, services_.procedural_faces, request.avatar);
  const bool person = request.connection != nullptr || !request.node.empty();
  const std::uint32_t id =
      simulation_.add_avatar(AvatarSetup{request.name, person, request.language, request.avatar.asset});
  if (id == 0) {
    services_.abuse.count_quietly(Abuse::room_full, 1);
    return refuse(request, codec::CloseCode::room_full, "room '" + name_ + "' is full; try another room");
  }
  OwnedMember member;
  member.address = request.address;
  member.node = request.node;
  member.order = next_order_++;
  member.resume_hash = request.connection ? resume_hash(request.resume) : request.resume_hash;
  member.language = request.language;
  member.info = {id, request.name, request.avatar.asset,
                 static_cast<std::uint32_t>(request.avatar.preview ? request.avatar.preview->size() : 0),
                 static_cast<std::uint32_t>(request.avatar.full ? request.avatar.full->size() : 0), person,
                 simulation_.seat(id)};
  member.avatar = request.avatar;
  give_own_face(id, member.avatar);
  const SharedBytes moved = reseat();
  // Counted before anyone hears of the joiner: whoever reads the counts
  // after a welcome or a presence message finds the joiner in them.
  if (person) counts_.persons.fetch_add(1);
  counts_.avatars.fetch_add(1);
  services_.metrics.avatars.fetch_add(1);
  introduce_to_others(members_, member);
  if (moved) broadcast_seats(moved);
  if (request.connection) {
    member.stream = welcome(members_, member, request, name_, services_.config.tick_hz, services_.metrics);
    counts_.local_persons.fetch_add(1);
    send_unit_morphs(member);
  }
  keep(member);
  send_down(bridge::down_joined(request.join_ref, record_of(member)));
  members_.emplace(id, std::move(member));
  // The joiner hears everyone's attention; the others hear the joiner's.
  const codec::Attention everyone = attention_now();
  codec::Attention joiner;
  for (const auto& entry : everyone.entries)
    if (entry.avatar == id) joiner.entries.push_back(entry);
  attention_sent_[id] = joiner.entries.front();
  broadcast_attention(joiner, id);
  if (request.connection) send_attention(members_.at(id), everyone);
  services_.abuse.event(request.address.empty() ? std::string_view("-") : std::string_view(request.address),
                        "room '" + name_ + "': " + request.name + " joined as avatar " + std::to_string(id) +
                            (person ? " (person)" : " (autonomous)"));
}

void OwnedRoom::give_own_face(std::uint32_t avatar, const StoredAvatar& face) {
  FaceModels* models = services_.face_models;
  if (!models || !face.full || face.full->empty() || face.version.empty()) return;
  if (auto built = models->find(face.version)) return simulation_.wear_face(avatar, std::move(built));
  // Tens of milliseconds: on the worker pool, while the room ticks on.
  boost::asio::post(services_.workers, [models, version = face.version, bytes = face.full, room = room_.weak_from_this(),
                                avatar]() mutable {
    std::string error;
    auto built = models->build(version, *bytes, error);
    // A package the store holds parses; one that does not keeps the generic face.
    if (!built) return;
    if (const auto open = room.lock()) open->wear_face(avatar, std::move(version), std::move(built));
  });
}

void OwnedRoom::wear_face(std::uint32_t avatar, const std::string& version, std::shared_ptr<const FaceModel> face) {
  const auto it = members_.find(avatar);
  if (it == members_.end() || it->second.avatar.version != version) return;  // gone, or wears another face now
  simulation_.wear_face(avatar, std::move(face));
}

std::size_t OwnedRoom::seats_of(const std::string& address) const {
  std::size_t seats = 0;
  for (const auto& [id, member] : members_) seats += member.person() && member.address == address;
  return seats;
}

std::size_t OwnedRoom::seats_of_block(const std::string& block) const {
  std::size_t seats = 0;
  for (const auto& [id, member] : members_) seats += member.person() && address_group(member.address) == block;
  return seats;
}

std::optional<std::pair<codec::CloseCode, std::string>> OwnedRoom::refusal_of(const JoinRequest& request) {
  const auto& config = services_.config;
  if (members_.size() >= config.room_size) {
    services_.abuse.count_quietly(Abuse::room_full, 1);
    return {{codec::CloseCode::room_full, "room '" + name_ + "' is full (" + std::to_string(config.room_size) +
                                              " avatars); try another room"}};
  }
  if ((request.connection || !request.node.empty()) && !request.address.empty()) {
    // One address cannot fill a room (the lobby least of all): the others
    // keep seats.
    const std::size_t share = config.abuse.seats_per_address != 0 ? config.abuse.seats_per_address
                                                                   : std::max<std::size_t>(1, config.room_size / 2);
    if (seats_of(request.address) >= share) {
      services_.abuse.note(Abuse::room_seats, request.address, "room '" + name_ + "' seats its share of them");
      return {{codec::CloseCode::room_full, "room '" + name_ + "' already seats " + std::to_string(share) +
                                                " people from your address, the most one address may hold; "
                                                "try another room"}};
    }
    // Nor can one network's addresses together.
    const std::size_t block_share = config.abuse.seats_per_block != 0
                                        ? config.abuse.seats_per_block
                                        : std::max<std::size_t>(1, config.room_size * 3 / 4);
    if (seats_of_block(address_group(request.address)) >= block_share) {
      services_.abuse.note(Abuse::room_seats, request.address, "room '" + name_ + "' seats its network's share");
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
    services_.abuse.note(Abuse::join_rate, request.address, "room '" + name_ + "' takes joins over its rate");
    return {{codec::CloseCode::rate_limited,
             "room '" + name_ + "' takes no more joins this moment; try again in " + whole_seconds(wait)}};
  }
  if (!simulation_.has_free_id()) {
    services_.abuse.count_quietly(Abuse::room_full, 1);
    return {{codec::CloseCode::server_full,
             "room '" + name_ + "' has handed out all its avatar ids lately; try again in a minute"}};
  }
  return std::nullopt;
}

void OwnedRoom::refuse(const JoinRequest& request, codec::CloseCode code, const std::string& why) {
  services_.metrics.rejected_joins.fetch_add(1);
  // Counted where the refusal was decided (refusal_of); logged with the rest.
  services_.abuse.event(request.address.empty() ? std::string_view("-") : std::string_view(request.address),
                        "room '" + name_ + "': " + request.name + " refused: " + why);
  if (request.connection) request.connection->close(code, why);
  else if (!request.node.empty())
    send_down(bridge::down_refused(request.join_ref, code, why));
  room_.close_if_unpeopled();  // a room made for this join alone goes again
}

void OwnedRoom::leave(std::uint32_t avatar) {
  auto it = members_.find(avatar);
  if (it == members_.end()) return;
  const bool person = it->second.person();
  if (it->second.stream) counts_.local_persons.fetch_sub(1);
  services_.abuse.event(it->second.address.empty() ? std::string_view("-") : std::string_view(it->second.address),
                        "room '" + name_ + "': " + it->second.info.name + " left");
  members_.erase(it);
  simulation_.remove_avatar(avatar);
  count_departure(members_, attention_sent_, counts_, services_.metrics, avatar, person);
  services_.bus.forget_member(name_, avatar);
  send_down(bridge::down_left(avatar));
  if (const SharedBytes moved = reseat()) broadcast_seats(moved);
  room_.close_if_unpeopled();
}

SharedBytes OwnedRoom::reseat() {
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

codec::Attention OwnedRoom::attention_now() const {
  codec::Attention attention;
  for (const auto& [id, member] : members_)
    if (attention.entries.size() < codec::kMaxWelcomeAvatars) attention.entries.push_back(simulation_.attention(id));
  return attention;
}

void OwnedRoom::send_attention_changes() {
  codec::Attention changed;
  for (const auto& entry : attention_now().entries) {
    codec::Attention::Entry& sent = attention_sent_[entry.avatar];
    if (sent == entry) continue;
    sent = entry;
    changed.entries.push_back(entry);
  }
  if (!changed.entries.empty()) broadcast_attention(changed);
}

void OwnedRoom::broadcast_seats(const SharedBytes& message) {
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_seats(message);
  // Every bridge keeps the room's seats and attention, people or not: it
  // welcomes its next joiner from them. (Only faces wait for bridged people.)
  send_down(bridge::down_message(bridge::DownKind::seats, 0, *message));
}

void OwnedRoom::broadcast_attention(const codec::Attention& attention, std::uint32_t except) {
  for (auto& [id, member] : members_)
    if (id != except && member.stream) member.stream->post_attention(attention);
  bridge::Bytes bytes;
  codec::write_message(attention, bytes);
  send_down(bridge::down_attention(std::move(bytes)));
}

void OwnedRoom::tell_line_begun(std::uint32_t avatar, const RoomEvent::LineBegun& line) {
  // Before this tick's frames, the line's first (PROTOCOL.md 5.15); the
  // streams of version-3 sessions leave it out.
  const auto speaking =
      encode_shared(codec::Speaking{avatar, line.frame_tick, line.duration_ms, line.language, line.text});
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_speaking(speaking);
  if (bridged_members() != 0) send_down(bridge::down_message(bridge::DownKind::speaking, 0, *speaking));
}

void OwnedRoom::broadcast_unit_morphs(std::uint32_t avatar) {
  const auto morphs = simulation_.unit_morphs(avatar);
  if (!morphs) return;
  const auto message = encode_shared(*morphs);
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_unit_morphs(avatar, message);
  // Every bridge keeps each avatar's newest set, people or not: it tells
  // its next joiner of it. The record keeps it for whoever takes over.
  send_down(bridge::down_message(bridge::DownKind::unit_morphs, avatar, *message));
  if (const auto it = members_.find(avatar); it != members_.end()) keep(it->second);
}

void OwnedRoom::send_unit_morphs(OwnedMember& member) {
  if (!member.stream) return;
  for (const auto& [id, other] : members_)
    if (const auto morphs = simulation_.unit_morphs(id)) member.stream->post_unit_morphs(id, encode_shared(*morphs));
}

void OwnedRoom::send_preview_surface() {
  const std::uint32_t every =
      std::max<std::uint32_t>(1, static_cast<std::uint32_t>(services_.config.tick_hz) / kPreviewSurfaceHz);
  if (simulation_.tick_index() % every != 0) return;
  for (auto& [id, member] : members_) {
    // A preview seats its owner alone: each member's page is its own face's.
    const auto surface = member.stream ? simulation_.preview_surface(id) : std::nullopt;
    if (!surface) continue;
    auto& sent = preview_surface_sent_[id];
    if (surface->moves == sent) continue;
    sent = surface->moves;
    member.stream->post_preview_surface(encode_shared(*surface));
  }
}

void OwnedRoom::tick(std::chrono::steady_clock::time_point due) {
  const RoomSimulation::TickFaces faces = begin_tick(due);
  FaceStepper::step_here(faces.faces, faces.dt_s);
  finish_tick();
}

RoomSimulation::TickFaces OwnedRoom::begin_tick(std::chrono::steady_clock::time_point due) {
  const auto start = std::chrono::steady_clock::now();
  const auto period = std::chrono::microseconds(1'000'000 / services_.config.tick_hz);
  // How late this tick starts tells the governor whether the pool keeps up;
  // its answer is how many of this room's faces run physics (level of detail).
  services_.physics_lod.observe_tick(due, start, period);
  simulation_.set_physics_share(services_.physics_lod.share());
  RoomSimulation::TickFaces faces = simulation_.begin_tick();
  tick_work_ = std::chrono::steady_clock::now() - start;
  return faces;
}

void OwnedRoom::finish_tick() {
  const auto start = std::chrono::steady_clock::now();
  simulation_.finish_tick();
  const std::size_t kinematic = simulation_.kinematic_faces();
  services_.metrics.kinematic_faces.fetch_add(static_cast<std::int64_t>(kinematic) -
                                              static_cast<std::int64_t>(counts_.kinematic_faces));
  counts_.kinematic_faces = kinematic;
  for (const RoomEvent& event : simulation_.take_events()) {
    spdlog::debug("room {}: tick {} avatar {}: {}", name_, event.tick, event.avatar, event.what);
    const auto writer = members_.find(event.avatar);
    if (!event.tell.empty() && writer != members_.end()) notice(writer->second, event.tell);
    if (event.line && writer != members_.end()) tell_line_begun(event.avatar, *event.line);
  }
  faces_.clear();
  for (const auto& [id, member] : members_) faces_.push_back({id, &simulation_.face(id)});
  face_sources_.offer(faces_);
  const std::uint64_t now_us = monotonic_us();
  const std::uint32_t tick = simulation_.tick_index();
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->tick(tick, now_us, faces_);
  if (bridged_members() != 0) {
    // Once per tick whatever the number of bridged people: each node encodes for its own.
    bridge::Down down = bridge::down_tick(tick);
    down.faces.reserve(faces_.size());
    for (const AvatarFace& face : faces_) down.faces.push_back({face.id, *face.face});
    send_down(down);
  }
  send_attention_changes();
  if (room_.preview()) send_preview_surface();
  if (++ticks_since_check_ >= static_cast<std::uint32_t>(services_.config.tick_hz)) {
    ticks_since_check_ = 0;
    keep_state();
    let_away_go();
    room_.close_if_unpeopled();
  }
  // The room's own work, both halves, not the wait for its faces' step.
  tick_work_ += std::chrono::steady_clock::now() - start;
  services_.metrics.observe_tick(std::chrono::duration<double>(tick_work_).count());
  services_.physics_lod.observe_room_work(std::chrono::duration<double>(tick_work_).count());
}

}  // namespace fw::server
