// OwnedRoom in a cluster: what the owner tells the bridging nodes and keeps
// in Redis for whoever takes it over, the requests bridged to it, taking a
// room over, and giving it up (owned_room.hpp, bridge_message.hpp).
#include <algorithm>

#include <spdlog/spdlog.h>

#include "owned_room.hpp"
#include "server_keys.hpp"

namespace fw::server {

bridge::MemberRecord OwnedRoom::record_of(const OwnedMember& member) const {
  bridge::MemberRecord record;
  record.info = member.info;
  record.node = member.stream ? services_.bus.node() : member.node;
  record.address = member.address;
  record.resume_hash = member.resume_hash;
  record.order = member.order;
  record.language = member.language;
  if (const auto morphs = simulation_.unit_morphs(member.info.id)) codec::write_message(*morphs, record.unit_morphs);
  return record;
}

void OwnedRoom::send_down(const bridge::Down& message) {
  bridge::Down copy = message;
  copy.owner = services_.bus.node();
  services_.bus.send_down(name_, bridge::encode(copy));
}

void OwnedRoom::keep(const OwnedMember& member) { services_.bus.keep_member(name_, record_of(member)); }

std::size_t OwnedRoom::bridged_members() const {
  std::size_t bridged = 0;
  for (const auto& [id, member] : members_) bridged += !member.node.empty() && !member.away_until;
  return bridged;
}

void OwnedRoom::answer_sync() {
  bridge::Down roster = bridge::down_roster();
  for (const auto& [id, member] : members_) roster.members.push_back(record_of(member));
  codec::write_message(attention_now(), roster.attention);
  send_down(roster);
}

void OwnedRoom::on_up(bridge::Up& message) {
  auto member = [&]() -> OwnedMember* {
    const auto it = members_.find(message.avatar);
    // Only the node that bridges a person speaks for them.
    return it != members_.end() && it->second.node == message.node ? &it->second : nullptr;
  };
  switch (message.kind) {
    case bridge::UpKind::sync: return answer_sync();
    case bridge::UpKind::join: {
      JoinRequest request;
      request.name = message.name;
      request.address = message.address;
      request.returning = message.returning;
      request.node = message.node;
      request.join_ref = message.join_ref;
      request.resume_hash = message.resume_hash;
      request.language = message.language;  // of the shape a hello allows (cluster_message_check.cpp)
      if (auto stored = services_.store.get(message.asset)) request.avatar = *stored;
      else
        return send_down(bridge::down_refused(message.join_ref, codec::CloseCode::avatar_being_prepared,
                                              "your face is still on its way to this room's server; try again"));
      return join(std::move(request));
    }
    case bridge::UpKind::leave:
      if (member()) leave(message.avatar);
      return;
    case bridge::UpKind::chat:
      if (member()) chat(message.avatar, std::move(message.text));
      return;
    case bridge::UpKind::command: {
      codec::Command command;
      // Posted again, as a command from a person here is.
      if (member() && codec::read_message(message.command, command) == codec::MessageError::ok)
        room_.command(message.avatar, std::move(command));
      return;
    }
  }
}

void OwnedRoom::keep_state() {
  bridge::RoomState state;
  for (const auto& [id, member] : members_) state.moods.push_back({id, simulation_.mood(id)});
  services_.bus.keep_state(name_, bridge::encode(state));
}

void OwnedRoom::keep_all() {
  for (const auto& [id, member] : members_) keep(member);
  keep_state();
}

void OwnedRoom::let_away_go() {
  const auto now = std::chrono::steady_clock::now();
  std::vector<std::uint32_t> gone;
  for (const auto& [id, member] : members_)
    if (member.away_until && *member.away_until <= now) gone.push_back(id);
  for (const std::uint32_t id : gone) {
    spdlog::info("room {}: {} did not come back; their seat goes", name_, members_.at(id).info.name);
    leave(id);
  }
}

void OwnedRoom::node_gone(const std::string& node) {
  const auto until = std::chrono::steady_clock::now() + services_.config.rejoin_grace;
  for (auto& [id, member] : members_)
    if (member.node == node && !member.away_until) {
      member.away_until = until;
      spdlog::info("room {}: {} is away (node {} stopped answering)", name_, member.info.name, node);
    }
}

void OwnedRoom::node_back(const std::string& node) {
  for (auto& [id, member] : members_)
    if (member.node == node && member.away_until) member.away_until.reset();
}

bool OwnedRoom::take_seat_back(JoinRequest& request) {
  if (request.returning.empty()) return false;
  const std::string hash = resume_hash(request.returning);
  const auto it = std::find_if(members_.begin(), members_.end(), [&](const auto& entry) {
    return entry.second.away_until && entry.second.resume_hash == hash;
  });
  if (it == members_.end()) return false;
  OwnedMember& member = it->second;
  member.away_until.reset();
  member.node = request.node;
  member.resume_hash = request.connection ? resume_hash(request.resume) : request.resume_hash;
  member.info.name = request.name;
  member.language = request.language;  // they may have chosen another on the way back
  simulation_.set_language(it->first, request.language);
  spdlog::info("room {}: {} is back as avatar {}", name_, request.name, it->first);
  if (request.connection) {
    member.stream = welcome(members_, member, request, name_, services_.config.tick_hz, services_.metrics);
    counts_.local_persons.fetch_add(1);
    send_attention(member, attention_now());
    send_unit_morphs(member);
  }
  keep(member);
  send_down(bridge::down_joined(request.join_ref, record_of(member), /*returning=*/true));
  return true;
}

void OwnedRoom::restore(std::vector<bridge::MemberRecord> records, std::optional<bridge::RoomState> state,
                        const std::set<std::string>& live_nodes, std::map<std::uint32_t, Member> here) {
  const std::string& node = services_.bus.node();
  std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  const auto away_until = std::chrono::steady_clock::now() + services_.config.rejoin_grace;
  std::size_t persons = 0;
  for (bridge::MemberRecord& record : records) {
    const std::uint32_t id = record.info.id;
    // Seated again in join order, under their ids: the same one leads.
    if (!simulation_.restore_avatar(id, AvatarSetup{record.info.name, record.info.person, record.language, record.info.asset}))
      continue;
    OwnedMember member;
    if (auto old = here.find(id); old != here.end()) {
      static_cast<Member&>(member) = std::move(old->second);
      here.erase(old);
    } else {
      member.avatar = stored_face_of(services_.store, record.info, name_);
    }
    member.info = record.info;
    member.address = record.address;
    member.language = record.language;
    member.resume_hash = record.resume_hash;
    member.order = record.order;
    next_order_ = std::max(next_order_, record.order + 1);
    if (member.stream) member.node.clear();  // connected here
    else if (record.node.empty()) member.node.clear();  // the room's own face
    else if (record.node != node && live_nodes.count(record.node)) member.node = record.node;
    else {
      member.node = record.node;
      member.away_until = away_until;  // their node is gone: they may come back with their resume key
    }
    restore_unit_morphs(record);
    persons += member.info.person;
    give_own_face(id, member.avatar);
    members_.emplace(id, std::move(member));
  }
  // Local people the records do not know (their join was in flight) come again.
  for (auto& [id, member] : here)
    if (member.stream) {
      member.stream->connection()->close(codec::CloseCode::shutting_down,
                                         "room '" + name_ + "' moved to another server; reconnect");
      counts_.local_persons.fetch_sub(1);
    }
  if (state)
    for (const auto& mood : state->moods)
      if (members_.count(mood.avatar)) simulation_.set_mood(mood.avatar, mood.values);
  counts_.persons.store(persons);
  const auto before = static_cast<std::int64_t>(counts_.avatars.exchange(members_.size()));
  services_.metrics.avatars.fetch_add(static_cast<std::int64_t>(members_.size()) - before);
  if (const SharedBytes moved = reseat()) broadcast_seats(moved);
  for (const auto& [id, member] : members_) keep(member);
  attention_sent_.clear();
  answer_sync();  // every bridging node learns the new owner and the roster
  spdlog::info("room {}: taken over with {} avatars ({} people)", name_, members_.size(), persons);
}

void OwnedRoom::restore_unit_morphs(const bridge::MemberRecord& record) {
  if (record.unit_morphs.empty()) return;
  codec::UnitMorphs set;
  // Read and checked with the record (cluster_message_check.cpp); what the
  // simulation refuses still leaves the avatar its shipped units.
  std::string error = codec::read_message(record.unit_morphs, set) == codec::MessageError::ok
                          ? simulation_.restore_unit_morphs(record.info.id, set)
                          : "unreadable";
  if (!error.empty())
    spdlog::warn("room {}: avatar {}'s redefined units not restored: {}", name_, record.info.id, error);
}

void OwnedRoom::step_down() {
  spdlog::warn("room {}: another node owns it now; the people here are asked to reconnect", name_);
  for (auto& [id, member] : members_)
    if (member.stream)
      member.stream->connection()->close(codec::CloseCode::shutting_down,
                                         "room '" + name_ + "' moved to another server; reconnect");
  services_.metrics.avatars.fetch_sub(static_cast<std::int64_t>(counts_.avatars.exchange(0)));
  members_.clear();
  attention_sent_.clear();
  counts_.local_persons.store(0);
  counts_.persons.store(0);
  for (const std::uint32_t id : simulation_.avatars()) simulation_.remove_avatar(id);
}

}  // namespace fw::server
