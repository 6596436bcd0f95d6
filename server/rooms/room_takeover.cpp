// Room in a cluster, as its owner: what it keeps in Redis for whoever takes
// it over, taking a room over, and giving it up (room.hpp).
#include <algorithm>

#include <spdlog/spdlog.h>

#include <boost/asio/post.hpp>

#include "room.hpp"
#include "room_bus.hpp"
#include "server_keys.hpp"

namespace fw::server {

namespace net = boost::asio;

void Room::keep_state() {
  bridge::RoomState state;
  for (const auto& [id, member] : members_) state.moods.push_back({id, simulation_.mood(id)});
  context_.bus->keep_state(name_, bridge::encode(state));
}

void Room::keep_all() {
  net::post(strand_, [self = shared_from_this()] {
    if (self->closed_ || self->role_ != RoomRole::owner || !self->context_.bus) return;
    for (const auto& [id, member] : self->members_) self->keep(member);
    self->keep_state();
  });
}

void Room::ask_roster() {
  net::post(strand_, [self = shared_from_this()] {
    if (self->closed_ || self->role_ != RoomRole::bridge) return;
    self->last_sync_ = {};
    self->context_.bus->send_up(
        self->name_, bridge::encode(bridge::up_sync(self->context_.bus->node())));
  });
}

void Room::let_away_go() {
  const auto now = std::chrono::steady_clock::now();
  std::vector<std::uint32_t> gone;
  for (const auto& [id, member] : members_)
    if (member.away_until && *member.away_until <= now) gone.push_back(id);
  for (const std::uint32_t id : gone) {
    spdlog::info("room {}: {} did not come back; their seat goes", name_, members_.at(id).info.name);
    do_leave(id);
  }
}

void Room::node_gone(std::string node) {
  net::post(strand_, [self = shared_from_this(), node = std::move(node)] {
    if (self->closed_ || self->role_ != RoomRole::owner) return;
    const auto until = std::chrono::steady_clock::now() + self->context_.config.rejoin_grace;
    for (auto& [id, member] : self->members_)
      if (member.node == node && !member.away_until) {
        member.away_until = until;
        spdlog::info("room {}: {} is away (node {} stopped answering)", self->name_, member.info.name, node);
      }
  });
}

void Room::node_back(std::string node) {
  net::post(strand_, [self = shared_from_this(), node = std::move(node)] {
    if (self->closed_ || self->role_ != RoomRole::owner) return;
    for (auto& [id, member] : self->members_)
      if (member.node == node && member.away_until) member.away_until.reset();
  });
}

bool Room::take_seat_back(JoinRequest& request) {
  if (request.returning.empty()) return false;
  const std::string hash = resume_hash(request.returning);
  const auto it = std::find_if(members_.begin(), members_.end(), [&](const auto& entry) {
    return entry.second.away_until && entry.second.resume_hash == hash;
  });
  if (it == members_.end()) return false;
  Member& member = it->second;
  member.away_until.reset();
  member.node = request.node;
  member.resume_hash = request.connection ? resume_hash(request.resume) : request.resume_hash;
  member.info.name = request.name;
  spdlog::info("room {}: {} is back as avatar {}", name_, request.name, it->first);
  if (request.connection) {
    member.stream = welcome(member, request);
    local_persons_.fetch_add(1);
    const auto bytes = encode_shared(attention_now());
    member.stream->charge(bytes->size());
    member.stream->connection()->deliver(bytes);
  }
  keep(member);
  send_down(bridge::down_joined(request.join_ref, record_of(member), /*returning=*/true));
  return true;
}

void Room::take_over(std::vector<bridge::MemberRecord> records, std::optional<bridge::RoomState> state,
                     std::set<std::string> live_nodes) {
  net::post(strand_, [self = shared_from_this(), records = std::move(records), state = std::move(state),
                      live_nodes = std::move(live_nodes)]() mutable {
    if (self->closed_) return;
    Room& room = *self;
    const std::string& here = room.context_.bus->node();
    std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
    room.role_ = RoomRole::owner;
    const auto away_until = std::chrono::steady_clock::now() + room.context_.config.rejoin_grace;
    std::map<std::uint32_t, Member> members;
    std::size_t persons = 0;
    for (bridge::MemberRecord& record : records) {
      const std::uint32_t id = record.info.id;
      // Seated again in join order, under their ids: the same one leads.
      if (!room.simulation_.restore_avatar(id, AvatarSetup{record.info.name, record.info.person})) continue;
      Member member;
      if (auto old = room.members_.find(id); old != room.members_.end()) member = std::move(old->second);
      else member.avatar = room.avatar_of(record.info);
      member.info = record.info;
      member.address = record.address;
      member.resume_hash = record.resume_hash;
      member.order = record.order;
      room.next_order_ = std::max(room.next_order_, record.order + 1);
      if (member.stream) member.node.clear();  // connected here
      else if (record.node.empty()) member.node.clear();  // the room's own face
      else if (record.node != here && live_nodes.count(record.node)) member.node = record.node;
      else {
        member.node = record.node;
        member.away_until = away_until;  // their node is gone: they may come back with their resume key
      }
      persons += member.info.person;
      members.emplace(id, std::move(member));
    }
    // Local people the records do not know (their join was in flight) come again.
    for (auto& [id, member] : room.members_)
      if (member.stream) {
        member.stream->connection()->close(codec::CloseCode::shutting_down,
                                           "room '" + room.name_ + "' moved to another server; reconnect");
        room.local_persons_.fetch_sub(1);
      }
    room.members_ = std::move(members);
    if (state)
      for (const auto& mood : state->moods)
        if (room.members_.count(mood.avatar)) room.simulation_.set_mood(mood.avatar, mood.values);
    room.person_count_.store(persons);
    const auto before = static_cast<std::int64_t>(room.avatar_count_.exchange(room.members_.size()));
    room.context_.metrics.avatars.fetch_add(static_cast<std::int64_t>(room.members_.size()) - before);
    if (const SharedBytes moved = room.reseat()) room.broadcast_seats(moved);
    for (const auto& [id, member] : room.members_) room.keep(member);
    room.attention_sent_.clear();
    room.answer_sync();  // every bridging node learns the new owner and the roster
    spdlog::info("room {}: taken over with {} avatars ({} people)", room.name_, room.members_.size(), persons);
    room.roster_ = false;
    // What waited for the old owner is this node's to seat now.
    std::vector<JoinRequest> waiting = std::exchange(room.held_joins_, {});
    for (auto& [ref, sent] : room.sent_joins_) waiting.push_back(std::move(sent.request));
    room.sent_joins_.clear();
    for (JoinRequest& request : waiting) {
      room.pending_joins_.fetch_add(1);
      room.do_join(std::move(request));
    }
  });
}

void Room::step_down() {
  net::post(strand_, [self = shared_from_this()] {
    if (self->closed_ || self->role_ != RoomRole::owner) return;
    Room& room = *self;
    spdlog::warn("room {}: another node owns it now; the people here are asked to reconnect", room.name_);
    room.role_ = RoomRole::bridge;
    for (auto& [id, member] : room.members_)
      if (member.stream)
        member.stream->connection()->close(codec::CloseCode::shutting_down,
                                           "room '" + room.name_ + "' moved to another server; reconnect");
    room.context_.metrics.avatars.fetch_sub(static_cast<std::int64_t>(room.avatar_count_.exchange(0)));
    room.members_.clear();
    room.attention_sent_.clear();
    room.local_persons_.store(0);
    room.person_count_.store(0);
    for (const std::uint32_t id : room.simulation_.avatars()) room.simulation_.remove_avatar(id);
    room.roster_ = false;
  });
}

}  // namespace fw::server
