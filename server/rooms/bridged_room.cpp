#include "bridged_room.hpp"

#include <spdlog/spdlog.h>

#include "monotonic_clock.hpp"
#include "server_keys.hpp"

namespace fw::server {

namespace {
// A bridging node asks the owner for its roster this often until it comes.
constexpr auto kSyncRetry = std::chrono::milliseconds(500);
// A tick whose faces are not the people this node knows (a join or a leave
// it never heard of, while Redis was away) asks for the roster again, at
// most this often.
constexpr auto kResyncOnDivergence = std::chrono::seconds(2);
// An up join the owner did not answer in this time is given up: the client
// is asked to come back (the owner may have died; a new one takes over).
constexpr auto kJoinAnswerTimeout = std::chrono::seconds(6);
}  // namespace

BridgedRoom::BridgedRoom(Room& room)
    : room_(room), services_(room.services()), name_(room.name()), counts_(room.counts()) {}

void BridgedRoom::send_up(const bridge::Up& message) { services_.bus.send_up(name_, bridge::encode(message)); }

void BridgedRoom::close() { close_every_member(members_); }

RoomHandover BridgedRoom::hand_over() {
  RoomHandover handover;
  handover.members = std::exchange(members_, {});
  handover.waiting_joins = std::exchange(held_joins_, {});
  for (auto& [ref, sent] : sent_joins_) handover.waiting_joins.push_back(std::move(sent.request));
  sent_joins_.clear();
  return handover;
}

void BridgedRoom::chat(std::uint32_t avatar, std::string text) {
  if (!members_.count(avatar)) return;
  send_up(bridge::up_chat(services_.bus.node(), avatar, std::move(text)));
}

void BridgedRoom::command(std::uint32_t avatar, const codec::Command& command) {
  if (!members_.count(avatar)) return;
  bridge::Bytes bytes;
  codec::write_message(command, bytes);
  send_up(bridge::up_command(services_.bus.node(), avatar, bytes));
}

void BridgedRoom::resync(std::uint32_t avatar, const std::vector<std::uint32_t>& avatars) {
  resync_member(members_, avatar, avatars);
}

void BridgedRoom::set_rate(std::uint32_t avatar, std::uint32_t bps) {
  set_member_budget(members_, avatar, bps, services_.config.default_client_bps, services_.config.max_client_bps);
}

void BridgedRoom::replace_deleted_avatar(const std::string& asset) {
  // The owner keeps the record of the new face; here only the viewers change.
  replace_deleted_face(members_, asset, services_.procedural_faces, name_, [](const Member&) {});
}

void BridgedRoom::leave(std::uint32_t avatar) {
  auto it = members_.find(avatar);
  if (it == members_.end()) return;
  // The owner says who left; until then the seat is the owner's.
  if (it->second.stream) counts_.local_persons.fetch_sub(1);
  it->second.stream.reset();
  send_up(bridge::up_leave(services_.bus.node(), avatar));
  room_.close_if_unpeopled();
}

void BridgedRoom::tick(std::chrono::steady_clock::time_point) {
  if (++ticks_since_check_ >= static_cast<std::uint32_t>(services_.config.tick_hz) / 4) {
    ticks_since_check_ = 0;
    housekeeping();
  }
}

void BridgedRoom::ask_roster() {
  last_sync_ = {};
  send_up(bridge::up_sync(services_.bus.node()));
}

void BridgedRoom::on_down(bridge::Down& message) {
  last_down_ = std::chrono::steady_clock::now();
  if (message.kind == bridge::DownKind::roster) return on_roster(message);
  if (!roster_) return;  // news before the roster: the roster will have it
  switch (message.kind) {
    case bridge::DownKind::roster: return;
    case bridge::DownKind::joined: return on_joined(message);
    case bridge::DownKind::refused: {
      const auto it = sent_joins_.find(message.join_ref);
      if (it == sent_joins_.end()) return;
      if (it->second.request.connection) it->second.request.connection->close(message.code, message.reason);
      sent_joins_.erase(it);
      return room_.close_if_unpeopled();
    }
    case bridge::DownKind::left: return on_left(message.avatar);
    case bridge::DownKind::seats: {
      codec::Seats seats;
      if (codec::read_message(message.message, seats) != codec::MessageError::ok) return;
      for (const auto& entry : seats.seats)
        if (const auto it = members_.find(entry.avatar); it != members_.end()) it->second.info.seat = entry.seat;
      const auto bytes = share(std::move(message.message));
      for (auto& [id, member] : members_)
        if (member.stream) member.stream->post_seats(bytes);
      return;
    }
    case bridge::DownKind::attention: {
      codec::Attention attention;
      if (codec::read_message(message.attention, attention) != codec::MessageError::ok) return;
      for (const auto& entry : attention.entries) attention_sent_[entry.avatar] = entry;
      for (auto& [id, member] : members_)
        if (member.stream) member.stream->post_attention(attention);
      return;
    }
    case bridge::DownKind::chat: {
      const auto line = share(std::move(message.message));
      for (auto& [id, member] : members_)
        if (member.stream && (message.avatar == 0 || message.avatar == id)) member.stream->post_chat(line);
      return;
    }
    case bridge::DownKind::speaking: {
      // The owner's tick news comes after it, so the line still goes before its frame here.
      const auto speaking = share(std::move(message.message));
      for (auto& [id, member] : members_)
        if (member.stream) member.stream->post_speaking(speaking);
      return;
    }
    case bridge::DownKind::result: {
      const auto it = members_.find(message.avatar);
      if (it != members_.end() && it->second.stream) it->second.stream->post_result(share(std::move(message.message)));
      return;
    }
    case bridge::DownKind::unit_morphs: return on_unit_morphs(message.avatar, std::move(message.message));
    case bridge::DownKind::tick: return on_tick(message);
  }
}

void BridgedRoom::join(JoinRequest request) {
  if (!request.connection) return;  // the room's own faces are the owner's to seat
  if (!roster_) {
    held_joins_.push_back(std::move(request));
    return housekeeping();
  }
  const std::string ref = services_.bus.node() + "/" + std::to_string(next_join_ref_++);
  bridge::Up up = bridge::up_sync(services_.bus.node());
  up.kind = bridge::UpKind::join;
  up.join_ref = ref;
  up.name = request.name;
  up.asset = request.avatar.asset;
  up.address = request.address;
  up.resume_hash = resume_hash(request.resume);
  up.returning = request.returning;
  up.language = request.language;
  send_up(up);
  sent_joins_.emplace(ref, SentJoin{std::move(request), std::chrono::steady_clock::now()});
}

void BridgedRoom::on_roster(bridge::Down& message) {
  // Everyone as the owner has them now. Local people keep their streams;
  // what changed since the last roster (another owner took over) is told
  // to them as presence.
  std::map<std::uint32_t, Member> members;
  std::vector<std::uint32_t> newcomers;
  for (bridge::MemberRecord& record : message.members) {
    const std::uint32_t id = record.info.id;
    auto old = members_.find(id);
    Member member;
    if (old != members_.end()) member = std::move(old->second);
    else member.avatar = stored_face_of(services_.store, record.info, name_);
    member.info = record.info;
    if (old != members_.end()) members_.erase(old);
    else newcomers.push_back(id);
    members.emplace(id, std::move(member));
  }
  // Whoever is here and not in the roster lost their seat (a room restored
  // without them): local people are asked to come back.
  for (auto& [id, gone] : members_) {
    if (gone.stream) {
      gone.stream->connection()->close(codec::CloseCode::shutting_down,
                                       "room '" + name_ + "' moved to another server; reconnect");
      counts_.local_persons.fetch_sub(1);
    }
    for (auto& [other_id, other] : members)
      if (other.stream) {
        other.stream->remove_avatar(id);
        codec::AvatarInfo info;
        info.id = id;
        other.stream->post_presence(codec::Presence::Change::left, id,
                                    encode_shared(codec::Presence{codec::Presence::Change::left, info}));
      }
  }
  members_ = std::move(members);
  // Newcomers are introduced once everyone is in place, to every local
  // person whatever the roster's order (introduced while the roster was
  // read, those listed before them were skipped: they had moved already).
  for (const std::uint32_t id : newcomers) introduce_to_others(members_, members_.at(id));
  // Each set after the presence that introduces its avatar (PROTOCOL.md 5.17).
  std::erase_if(unit_morphs_, [&](const auto& kept) { return !members_.count(kept.first); });
  for (bridge::MemberRecord& record : message.members)
    if (!record.unit_morphs.empty()) on_unit_morphs(record.info.id, std::move(record.unit_morphs));
  std::size_t persons = 0;
  for (const auto& [id, member] : members_) persons += member.info.person;
  counts_.persons.store(persons);
  const auto before = static_cast<std::int64_t>(counts_.avatars.exchange(members_.size()));
  services_.metrics.avatars.fetch_add(static_cast<std::int64_t>(members_.size()) - before);
  codec::Attention attention;
  if (codec::read_message(message.attention, attention) == codec::MessageError::ok)
    for (const auto& entry : attention.entries) attention_sent_[entry.avatar] = entry;
  const bool first = !roster_;
  roster_ = true;
  if (first) spdlog::info("room {}: bridged to its owner {} ({} avatars)", name_, message.owner, members_.size());
  for (JoinRequest& request : std::exchange(held_joins_, {})) join(std::move(request));
}

void BridgedRoom::on_joined(bridge::Down& message) {
  const std::uint32_t id = message.member.info.id;
  const auto sent = sent_joins_.find(message.join_ref);
  auto existing = members_.find(id);
  if (existing == members_.end()) {
    Member member;
    member.info = message.member.info;
    member.avatar = stored_face_of(services_.store, member.info, name_);
    introduce_to_others(members_, member);
    existing = members_.emplace(id, std::move(member)).first;
    counts_.avatars.fetch_add(1);
    services_.metrics.avatars.fetch_add(1);
    if (existing->second.info.person) counts_.persons.fetch_add(1);
  }
  if (!message.member.unit_morphs.empty()) on_unit_morphs(id, std::move(message.member.unit_morphs));
  if (sent == sent_joins_.end()) return;
  JoinRequest request = std::move(sent->second.request);
  sent_joins_.erase(sent);
  Member& seated = existing->second;
  seated.stream = welcome(members_, seated, request, name_, services_.config.tick_hz, services_.metrics);
  counts_.local_persons.fetch_add(1);
  codec::Attention everyone;
  for (const auto& [avatar, entry] : attention_sent_)
    if (members_.count(avatar) && everyone.entries.size() < codec::kMaxWelcomeAvatars)
      everyone.entries.push_back(entry);
  send_attention(seated, everyone);
  // Every avatar's redefined units after the welcome, as the owner tells its own newcomers.
  for (const auto& [avatar, set] : unit_morphs_) seated.stream->post_unit_morphs(avatar, set);
  services_.abuse.event(request.address.empty() ? std::string_view("-") : std::string_view(request.address),
                        "room '" + name_ + "': " + request.name + " joined as avatar " + std::to_string(id) +
                            " (bridged to " + message.owner + ")");
}

void BridgedRoom::on_left(std::uint32_t avatar) {
  auto it = members_.find(avatar);
  if (it == members_.end()) return;
  if (it->second.stream) {
    // The owner let a local person go (the rejoin grace ended, say).
    it->second.stream->connection()->close(codec::CloseCode::normal, "you left room '" + name_ + "'");
    counts_.local_persons.fetch_sub(1);
  }
  const bool person = it->second.info.person;
  members_.erase(it);
  unit_morphs_.erase(avatar);
  count_departure(members_, attention_sent_, counts_, services_.metrics, avatar, person);
  room_.close_if_unpeopled();
}

void BridgedRoom::on_unit_morphs(std::uint32_t avatar, bridge::Bytes set) {
  if (!members_.count(avatar)) return;  // a set of an avatar never introduced here: the next roster has it
  SharedBytes& kept = unit_morphs_[avatar];
  if (kept && *kept == set) return;
  kept = share(std::move(set));
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->post_unit_morphs(avatar, kept);
}

void BridgedRoom::on_tick(bridge::Down& message) {
  // The owner's faces of this tick, encoded here for each local subscriber
  // at its own rate, as the owner does for its own.
  bridged_faces_.clear();
  bridged_faces_.reserve(message.faces.size());
  faces_.clear();
  std::size_t known = 0;
  for (const bridge::FaceEntry& entry : message.faces) {
    if (!members_.count(entry.id)) continue;
    ++known;
    bridged_faces_.push_back(entry.face);
  }
  // The owner sends every member's face each tick: other faces, or fewer,
  // mean this node's roster fell behind (news lost while Redis was down).
  const auto now = std::chrono::steady_clock::now();
  if ((known != message.faces.size() || known != members_.size()) && now - last_resync_ >= kResyncOnDivergence) {
    last_resync_ = now;
    spdlog::info("room {}: the owner's faces differ from the people known here; asking for the roster", name_);
    send_up(bridge::up_sync(services_.bus.node()));
  }
  std::size_t next = 0;
  for (const bridge::FaceEntry& entry : message.faces)
    if (members_.count(entry.id)) faces_.push_back({entry.id, &bridged_faces_[next++]});
  face_sources_.offer(faces_);
  const std::uint64_t now_us = monotonic_us();
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->tick(message.tick, now_us, faces_);
}

void BridgedRoom::housekeeping() {
  const auto now = std::chrono::steady_clock::now();
  if (!roster_ && now - last_sync_ >= kSyncRetry) {
    last_sync_ = now;
    send_up(bridge::up_sync(services_.bus.node()));
  }
  for (auto it = sent_joins_.begin(); it != sent_joins_.end();) {
    if (now - it->second.sent < kJoinAnswerTimeout) {
      ++it;
      continue;
    }
    if (it->second.request.connection)
      it->second.request.connection->close(codec::CloseCode::shutting_down,
                                           "room '" + name_ + "' did not answer in time; reconnect");
    it = sent_joins_.erase(it);
  }
  room_.close_if_unpeopled();
}

}  // namespace fw::server
