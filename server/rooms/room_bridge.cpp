// Room in a cluster: what the owner tells the bridging nodes, and how a
// bridging node serves its own clients from the owner's news (room.hpp,
// bridge_message.hpp). Runs on the room's strand like the rest of Room.
#include <spdlog/spdlog.h>

#include <boost/asio/post.hpp>

#include "monotonic_clock.hpp"
#include "room.hpp"
#include "room_bus.hpp"
#include "server_keys.hpp"

namespace fw::server {

namespace net = boost::asio;

namespace {
// A bridging node asks the owner for its roster this often until it comes.
constexpr auto kSyncRetry = std::chrono::milliseconds(500);
// An up join the owner did not answer in this time is given up: the client
// is asked to come back (the owner may have died; a new one takes over).
constexpr auto kJoinAnswerTimeout = std::chrono::seconds(6);
}  // namespace

bridge::MemberRecord Room::record_of(const Member& member) const {
  bridge::MemberRecord record;
  record.info = member.info;
  record.node = member.stream ? context_.bus->node() : member.node;
  record.address = member.address;
  record.resume_hash = member.resume_hash;
  record.order = member.order;
  return record;
}

void Room::send_down(const bridge::Down& message) {
  if (!context_.bus) return;
  bridge::Down copy = message;
  copy.owner = context_.bus->node();
  context_.bus->send_down(name_, bridge::encode(copy));
}

void Room::keep(const Member& member) {
  if (context_.bus) context_.bus->keep_member(name_, record_of(member));
}

std::size_t Room::bridged_members() const {
  std::size_t bridged = 0;
  for (const auto& [id, member] : members_) bridged += !member.node.empty() && !member.away_until;
  return bridged;
}

void Room::answer_sync() {
  bridge::Down roster = bridge::down_roster();
  for (const auto& [id, member] : members_) roster.members.push_back(record_of(member));
  codec::write_message(attention_now(), roster.attention);
  send_down(roster);
}

StoredAvatar Room::avatar_of(const codec::AvatarInfo& info) const {
  if (auto stored = context_.store->get(info.asset)) return *stored;
  spdlog::warn("room {}: the face of avatar {} ({}) is not here; its viewers here go without it", name_, info.id,
               info.asset);
  StoredAvatar missing;
  missing.asset = info.asset;
  return missing;
}

void Room::on_up(bridge::Up message) {
  net::post(strand_, [self = shared_from_this(), message = std::move(message)]() mutable {
    if (self->closed_ || self->role_ != RoomRole::owner) return;
    auto member = [&]() -> Member* {
      const auto it = self->members_.find(message.avatar);
      // Only the node that bridges a person speaks for them.
      return it != self->members_.end() && it->second.node == message.node ? &it->second : nullptr;
    };
    switch (message.kind) {
      case bridge::UpKind::sync: return self->answer_sync();
      case bridge::UpKind::join: {
        JoinRequest request;
        request.name = message.name;
        request.address = message.address;
        request.returning = message.returning;
        request.node = message.node;
        request.join_ref = message.join_ref;
        request.resume_hash = message.resume_hash;
        if (auto stored = self->context_.store->get(message.asset)) request.avatar = *stored;
        else
          return self->send_down(bridge::down_refused(
              message.join_ref, codec::CloseCode::avatar_being_prepared,
              "your face is still on its way to this room's server; try again"));
        self->pending_joins_.fetch_add(1);
        return self->do_join(std::move(request));
      }
      case bridge::UpKind::leave:
        if (member()) self->do_leave(message.avatar);
        return;
      case bridge::UpKind::chat:
        if (member()) self->do_chat(message.avatar, std::move(message.text));
        return;
      case bridge::UpKind::command: {
        codec::Command command;
        if (member() && codec::read_message(message.command, command) == codec::MessageError::ok)
          self->command(message.avatar, std::move(command));
        return;
      }
    }
  });
}

void Room::on_down(bridge::Down message) {
  net::post(strand_, [self = shared_from_this(), message = std::move(message)]() mutable {
    if (self->closed_ || self->role_ != RoomRole::bridge) return;
    self->last_down_ = std::chrono::steady_clock::now();
    if (message.kind == bridge::DownKind::roster) return self->on_roster(message);
    if (!self->roster_) return;  // news before the roster: the roster will have it
    switch (message.kind) {
      case bridge::DownKind::roster: return;
      case bridge::DownKind::joined: return self->on_joined(message);
      case bridge::DownKind::refused: {
        const auto it = self->sent_joins_.find(message.join_ref);
        if (it == self->sent_joins_.end()) return;
        if (it->second.request.connection) it->second.request.connection->close(message.code, message.reason);
        self->sent_joins_.erase(it);
        return self->close_if_unpeopled();
      }
      case bridge::DownKind::left: return self->on_left(message.avatar);
      case bridge::DownKind::seats: {
        codec::Seats seats;
        if (codec::read_message(message.message, seats) != codec::MessageError::ok) return;
        for (const auto& entry : seats.seats)
          if (const auto it = self->members_.find(entry.avatar); it != self->members_.end())
            it->second.info.seat = entry.seat;
        const auto bytes = share(std::move(message.message));
        for (auto& [id, member] : self->members_)
          if (member.stream) member.stream->post_seats(bytes);
        return;
      }
      case bridge::DownKind::attention: {
        codec::Attention attention;
        if (codec::read_message(message.attention, attention) != codec::MessageError::ok) return;
        for (const auto& entry : attention.entries) self->attention_sent_[entry.avatar] = entry;
        for (auto& [id, member] : self->members_)
          if (member.stream) member.stream->post_attention(attention);
        return;
      }
      case bridge::DownKind::chat: {
        const auto line = share(std::move(message.message));
        for (auto& [id, member] : self->members_)
          if (member.stream && (message.avatar == 0 || message.avatar == id)) member.stream->post_chat(line);
        return;
      }
      case bridge::DownKind::result: {
        const auto it = self->members_.find(message.avatar);
        if (it != self->members_.end() && it->second.stream)
          it->second.stream->post_result(share(std::move(message.message)));
        return;
      }
      case bridge::DownKind::tick: return self->bridge_tick(message);
    }
  });
}

void Room::bridge_join(JoinRequest request) {
  if (!request.connection) return;  // the room's own faces are the owner's to seat
  if (!roster_) {
    held_joins_.push_back(std::move(request));
    return bridge_housekeeping();
  }
  const std::string ref = context_.bus->node() + "/" + std::to_string(next_join_ref_++);
  bridge::Up up = bridge::up_sync(context_.bus->node());
  up.kind = bridge::UpKind::join;
  up.join_ref = ref;
  up.name = request.name;
  up.asset = request.avatar.asset;
  up.address = request.address;
  up.resume_hash = resume_hash(request.resume);
  up.returning = request.returning;
  context_.bus->send_up(name_, bridge::encode(up));
  sent_joins_.emplace(ref, SentJoin{std::move(request), std::chrono::steady_clock::now()});
}

void Room::on_roster(bridge::Down& message) {
  // Everyone as the owner has them now. Local people keep their streams;
  // what changed since the last roster (another owner took over) is told
  // to them as presence.
  std::map<std::uint32_t, Member> members;
  for (bridge::MemberRecord& record : message.members) {
    const std::uint32_t id = record.info.id;
    auto old = members_.find(id);
    Member member;
    if (old != members_.end()) member = std::move(old->second);
    else member.avatar = avatar_of(record.info);
    member.info = record.info;
    member.node = record.node == context_.bus->node() ? "" : record.node;
    if (old == members_.end())
      for (auto& [other_id, other] : members_)
        if (other.stream) {
          other.stream->post_presence(codec::Presence::Change::joined, id,
                                      encode_shared(codec::Presence{codec::Presence::Change::joined, member.info}));
          other.stream->add_avatar(id, member.avatar.preview, member.avatar.full);
        }
    if (old != members_.end()) members_.erase(old);
    members.emplace(id, std::move(member));
  }
  // Whoever is here and not in the roster lost their seat (a room restored
  // without them): local people are asked to come back.
  for (auto& [id, gone] : members_) {
    if (gone.stream) {
      gone.stream->connection()->close(codec::CloseCode::shutting_down,
                                       "room '" + name_ + "' moved to another server; reconnect");
      local_persons_.fetch_sub(1);
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
  std::size_t persons = 0;
  for (const auto& [id, member] : members_) persons += member.info.person;
  person_count_.store(persons);
  const auto before = static_cast<std::int64_t>(avatar_count_.exchange(members_.size()));
  context_.metrics.avatars.fetch_add(static_cast<std::int64_t>(members_.size()) - before);
  codec::Attention attention;
  if (codec::read_message(message.attention, attention) == codec::MessageError::ok)
    for (const auto& entry : attention.entries) attention_sent_[entry.avatar] = entry;
  const bool first = !roster_;
  roster_ = true;
  if (first) spdlog::info("room {}: bridged to its owner {} ({} avatars)", name_, message.owner, members_.size());
  for (JoinRequest& request : std::exchange(held_joins_, {})) bridge_join(std::move(request));
}

void Room::on_joined(bridge::Down& message) {
  const std::uint32_t id = message.member.info.id;
  const auto sent = sent_joins_.find(message.join_ref);
  auto existing = members_.find(id);
  if (existing == members_.end()) {
    Member member;
    member.info = message.member.info;
    member.avatar = avatar_of(member.info);
    member.node = message.member.node == context_.bus->node() ? "" : message.member.node;
    introduce_to_others(member);
    existing = members_.emplace(id, std::move(member)).first;
    avatar_count_.fetch_add(1);
    context_.metrics.avatars.fetch_add(1);
    if (existing->second.info.person) person_count_.fetch_add(1);
  } else {
    existing->second.node = message.member.node == context_.bus->node() ? "" : message.member.node;
  }
  if (sent == sent_joins_.end()) return;
  JoinRequest request = std::move(sent->second.request);
  sent_joins_.erase(sent);
  Member& seated = existing->second;
  seated.node.clear();
  seated.local_gone = false;
  seated.stream = welcome(seated, request);
  local_persons_.fetch_add(1);
  codec::Attention everyone;
  for (const auto& [avatar, entry] : attention_sent_)
    if (members_.count(avatar) && everyone.entries.size() < codec::kMaxWelcomeAvatars)
      everyone.entries.push_back(entry);
  const auto bytes = encode_shared(everyone);
  seated.stream->charge(bytes->size());
  seated.stream->connection()->deliver(bytes);
  context_.abuse.event(request.address.empty() ? std::string_view("-") : std::string_view(request.address),
                       "room '" + name_ + "': " + request.name + " joined as avatar " + std::to_string(id) +
                           " (bridged to " + message.owner + ")");
}

void Room::on_left(std::uint32_t avatar) {
  auto it = members_.find(avatar);
  if (it == members_.end()) return;
  if (it->second.stream) {
    // The owner let a local person go (the rejoin grace ended, say).
    it->second.stream->connection()->close(codec::CloseCode::normal, "you left room '" + name_ + "'");
    local_persons_.fetch_sub(1);
  }
  const bool person = it->second.info.person;
  members_.erase(it);
  attention_sent_.erase(avatar);
  avatar_count_.fetch_sub(1);
  context_.metrics.avatars.fetch_sub(1);
  if (person) person_count_.fetch_sub(1);
  codec::AvatarInfo info;
  info.id = avatar;
  info.person = person;
  const auto left = encode_shared(codec::Presence{codec::Presence::Change::left, info});
  for (auto& [id, member] : members_) {
    if (!member.stream) continue;
    member.stream->remove_avatar(avatar);
    member.stream->post_presence(codec::Presence::Change::left, avatar, left);
  }
  close_if_unpeopled();
}

void Room::bridge_tick(bridge::Down& message) {
  // The owner's faces of this tick, encoded here for each local subscriber
  // at its own rate, as the owner does for its own.
  bridged_faces_.clear();
  bridged_faces_.reserve(message.faces.size());
  faces_.clear();
  for (const bridge::FaceEntry& entry : message.faces) {
    if (!members_.count(entry.id)) continue;
    bridged_faces_.push_back(entry.face);
  }
  std::size_t next = 0;
  for (const bridge::FaceEntry& entry : message.faces)
    if (members_.count(entry.id)) faces_.push_back({entry.id, &bridged_faces_[next++]});
  const std::uint64_t now_us = monotonic_us();
  for (auto& [id, member] : members_)
    if (member.stream) member.stream->tick(message.tick, now_us, faces_);
}

void Room::bridge_housekeeping() {
  const auto now = std::chrono::steady_clock::now();
  if (!roster_ && now - last_sync_ >= kSyncRetry) {
    last_sync_ = now;
    context_.bus->send_up(name_, bridge::encode(bridge::up_sync(context_.bus->node())));
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
  close_if_unpeopled();
}

}  // namespace fw::server
