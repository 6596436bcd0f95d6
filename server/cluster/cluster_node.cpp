#include "cluster_node.hpp"

#include <future>

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "client_session.hpp"
#include "cluster_keys.hpp"
#include "cluster_limits.hpp"
#include "cluster_message_check.hpp"
#include "demo_room.hpp"
#include "room.hpp"
#include "room_bus_relay.hpp"
#include "room_registry.hpp"
#include "session_registry.hpp"

namespace fw::server {

namespace net = boost::asio;
namespace keys = cluster_keys;

namespace {

// A node reports twice a second that it lives (its key lasts 2 s) and
// renews its leases (3 s): an owner that dies is replaced within about
// 3.5 s, and a node that misses one beat under load loses nothing.
constexpr auto kBeat = std::chrono::milliseconds(500);
constexpr auto kAliveMs = 2000;
constexpr auto kLeaseMs = 3000;
// Without Redis a room someone joins waits this long for it, then is owned
// here (a node just started is usually connected by then).
constexpr auto kOwnWithoutRedisAfter = std::chrono::seconds(3);
// After (re)connecting, nodes are not taken for dead before they could
// have reported (a beat or two past their liveness key's life).
constexpr auto kSettleAfterConnect = std::chrono::milliseconds(kAliveMs + 1000);
// What a room placed on a node adds to its load until the node reports
// again (about the load of a few people).
constexpr double kRoomPlacementLoad = 2.0;
// The owner keeps this many chat lines of a room in Redis.
constexpr int kChatTail = 50;
// Faces waiting for Redis past this many bytes are dropped (the next tick
// carries newer ones) rather than queued behind a slow Redis.
constexpr std::size_t kMaxWaitingOutput = 8 * 1024 * 1024;

// Renews the lease when this node holds it, takes it when nobody does:
// 1 held, 0 another node's.
const std::string kRenewLease = R"(
local owner = redis.call('GET', KEYS[1])
if owner == ARGV[1] then redis.call('PEXPIRE', KEYS[1], ARGV[2]) return 1 end
if owner then return 0 end
redis.call('SET', KEYS[1], ARGV[1], 'PX', ARGV[2])
return 1)";
const std::string kReleaseLease = R"(
if redis.call('GET', KEYS[1]) == ARGV[1] then return redis.call('DEL', KEYS[1]) end
return 0)";

std::string text(const bridge::Bytes& bytes) { return {bytes.begin(), bytes.end()}; }

}  // namespace

ClusterNode::ClusterNode(const ClusterServices& services, net::any_io_executor executor, RedisAddress address,
                         std::string node)
    : services_(services), strand_(net::make_strand(executor)), address_(address), node_(std::move(node)),
      timer_(strand_), avatars_(address, std::chrono::milliseconds(2000)) {
  adopt_server_key();
  keep_avatars_in_redis();
  keep_looks_in_redis();
}

ClusterNode::~ClusterNode() {
  services_.store.set_replica({});
  services_.tokens.on_news({});
}

void ClusterNode::start() {
  services_.room_bus.attach(*this);
  services_.state.cluster_up = false;
  services_.addresses.share_spending();
  // A token taken or let go here is news for every node at once.
  services_.tokens.on_news([this](const TokenNews& news) {
    LimitsNews limits;
    limits.node = node_;
    limits.tokens = {news};
    net::post(strand_, [this, message = encode_limits(limits)] {
      if (up_ && commands_) commands_->command({"PUBLISH", keys::kLimitsChannel, message});
    });
  });
  net::post(strand_, [this] {
    connect();
    schedule_heartbeat();
  });
}

void ClusterNode::stop() {
  auto done = std::make_shared<std::promise<void>>();
  net::post(strand_, [this, done] {
    stopped_ = true;
    timer_.cancel();
    if (up_) {
      for (const auto& room : owned_) commands_->command({"EVAL", kReleaseLease, "1", keys::room_owner(room), node_});
      commands_->command({"DEL", keys::node_alive(node_)});
      commands_->command({"SREM", keys::kNodes, node_}, [done](const RedisReply*) { done->set_value(); });
    } else {
      done->set_value();
    }
  });
  // The I/O loop may already be stopped: then nothing can be said to Redis.
  if (done->get_future().wait_for(std::chrono::seconds(2)) != std::future_status::ready)
    spdlog::warn("left the cluster without telling Redis: others take this node's rooms over when its leases end");
  services_.room_bus.detach();
}

void ClusterNode::connect() {
  if (connecting_ || stopped_) return;
  connecting_ = true;
  RedisConnection::Options options;
  options.client_name = "facewire-" + node_;
  for (char& c : options.client_name)
    if (c == ' ') c = '_';
  commands_ = RedisConnection::create(strand_, address_, options);
  subscriber_ = RedisConnection::create(strand_, address_, options);
  auto pending = std::make_shared<int>(2);
  auto failed = std::make_shared<std::string>();
  auto done = [this, pending, failed](const std::string& error) {
    if (!error.empty() && failed->empty()) *failed = error;
    if (--*pending != 0) return;
    connecting_ = false;
    if (!failed->empty()) {
      if (beats_ % 20 == 0) spdlog::warn("cluster: Redis not reachable ({}); trying again", *failed);
      commands_.reset();
      subscriber_.reset();
      return;
    }
    on_connected();
  };
  commands_->connect(done);
  subscriber_->connect(done);
}

void ClusterNode::on_connected() {
  commands_->on_lost([this](const std::string& why) { lost(why); });
  subscriber_->on_lost([this](const std::string& why) { lost(why); });
  subscriber_->on_message([this](std::string_view channel, std::string_view payload) { on_message(channel, payload); });
  std::vector<std::string> channels{keys::node_inbox(node_), keys::kLimitsChannel, keys::kAvatarDeletions};
  for (const auto& room : owned_) channels.push_back(keys::room_up(room));
  for (const auto& room : bridged_) channels.push_back(keys::room_down(room));
  subscriber_->subscribe(channels);
  connected_since_ = Clock::now();
  up_ = true;  // ready (/readyz) once it knows the other nodes (watch_nodes)
  spdlog::info("cluster: node {} connected to Redis at {} ({} rooms owned, {} bridged)", node_, to_string(address_),
               owned_.size(), bridged_.size());
  report_alive();
  // Back after Redis was away: leases, records and avatars are written again
  // (Redis may have restarted empty), bridges ask for a fresh roster.
  renew_leases();
  for (const auto& name : owned_) {
    commands_->command({"SADD", keys::kRooms, name});
    if (auto room = services_.rooms.find(name)) room->keep_all();
  }
  for (const auto& name : bridged_)
    if (auto room = services_.rooms.find(name)) room->ask_roster();
  reshare_avatars();
  watch_nodes();
  for (const auto& room : std::exchange(unplaced_, {})) place(room);
}

void ClusterNode::lost(const std::string& why) {
  if (!up_) return;
  up_ = false;
  waiting_since_ = Clock::now();
  services_.state.cluster_up = false;
  spdlog::warn("cluster: lost Redis ({}); serving the rooms owned here, not ready until it is back", why);
  if (commands_) commands_->close();
  if (subscriber_) subscriber_->close();
  commands_.reset();
  subscriber_.reset();
  // What waited for a read from Redis is dropped: bridges ask for a roster when it is back.
  held_down_.clear();
  held_from_.clear();
}

void ClusterNode::schedule_heartbeat() {
  timer_.expires_after(kBeat);
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || stopped_) return;
    heartbeat();
    schedule_heartbeat();
  });
}

void ClusterNode::heartbeat() {
  ++beats_;
  if (!up_) {
    if (!unplaced_.empty() && Clock::now() - waiting_since_ >= kOwnWithoutRedisAfter) own_unplaced();
    return connect();
  }
  report_alive();
  share_limits();
  renew_leases();
  watch_nodes();
  adopt_orphans();
}

void ClusterNode::report_alive() {
  // Load: people connected here, and faces simulated here (a tenth each).
  std::size_t avatars = 0;
  for (const auto& name : owned_)
    if (auto room = services_.rooms.find(name)) avatars += room->avatar_count();
  const double load = static_cast<double>(services_.sessions.count()) + 0.1 * static_cast<double>(avatars);
  commands_->command({"SET", keys::node_alive(node_), std::to_string(load), "PX", std::to_string(kAliveMs)});
  commands_->command({"SADD", keys::kNodes, node_});
}

void ClusterNode::renew_leases() {
  for (const auto& name : owned_) {
    commands_->command(
        {"EVAL", kRenewLease, "1", keys::room_owner(name), node_, std::to_string(kLeaseMs)},
        [this, name](const RedisReply* reply) {
          if (!reply || reply->type != RedisReply::Type::integer || reply->integer == 1 || !owned_.count(name)) return;
          // Another node took the room while this one could not renew.
          spdlog::warn("cluster: room {} has another owner now; bridging to it", name);
          owned_.erase(name);
          if (subscriber_) subscriber_->unsubscribe({keys::room_up(name)});
          if (auto room = services_.rooms.find(name)) room->step_down();
          bridge(name);
        });
  }
}

void ClusterNode::watch_nodes() {
  commands_->command({"SMEMBERS", keys::kNodes}, [this](const RedisReply* nodes) {
    if (!nodes || nodes->type != RedisReply::Type::array || !commands_) return;
    std::vector<std::string> args{"MGET"}, names;
    for (const auto& n : nodes->elements) {
      names.push_back(n.text);
      args.push_back(keys::node_alive(n.text));
    }
    if (names.empty()) return;
    commands_->command(args, [this, names](const RedisReply* alive) {
      if (!alive || alive->elements.size() != names.size()) return;
      std::set<std::string> live;
      loads_.clear();
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (alive->elements[i].type != RedisReply::Type::string) {
          if (commands_) commands_->command({"SREM", keys::kNodes, names[i]});
          continue;
        }
        live.insert(names[i]);
        loads_[names[i]] = std::atof(alive->elements[i].text.c_str());
      }
      live.insert(node_);
      // Just (re)connected, Redis may have restarted empty: the others have
      // not reported yet, and are not taken for dead until they could have.
      if (Clock::now() - connected_since_ < kSettleAfterConnect)
        for (const auto& known : live_) live.insert(known);
      for (const auto& back : live)
        if (!live_.count(back))
          for (const auto& name : owned_)
            if (auto room = services_.rooms.find(name)) room->node_back(back);
      for (const auto& gone : live_)
        if (!live.count(gone)) {
          spdlog::warn("cluster: node {} stopped answering; its people in rooms owned here are away", gone);
          services_.addresses.set_remote_connections(gone, {});
          for (const auto& name : owned_)
            if (auto room = services_.rooms.find(name)) room->node_gone(gone);
        }
      live_ = std::move(live);
      // Knowing the others and their loads, it can place rooms: ready.
      if (up_) services_.state.cluster_up = true;
    });
  });
}

void ClusterNode::adopt_orphans() {
  // Rooms whose owner's lease ran out (it died) are taken by whoever is first.
  commands_->command({"SMEMBERS", keys::kRooms}, [this](const RedisReply* rooms) {
    if (!rooms || rooms->type != RedisReply::Type::array || rooms->elements.empty() || !commands_) return;
    std::vector<std::string> args{"MGET"}, names;
    for (const auto& r : rooms->elements) {
      if (owned_.count(r.text)) continue;
      names.push_back(r.text);
      args.push_back(keys::room_owner(r.text));
    }
    if (names.empty()) return;
    commands_->command(args, [this, names](const RedisReply* owners) {
      if (!owners || owners->elements.size() != names.size()) return;
      for (std::size_t i = 0; i < names.size(); ++i)
        if (owners->elements[i].is_nil()) acquire(names[i]);
    });
  });
}

std::string ClusterNode::least_loaded() const {
  std::string best = node_;
  double best_load = loads_.count(node_) ? loads_.at(node_) : 0.0;
  for (const auto& [name, load] : loads_)
    if (live_.count(name) && (load < best_load || (load == best_load && name < best))) {
      best = name;
      best_load = load;
    }
  return best;
}

void ClusterNode::room_opened(const std::string& room) {
  net::post(strand_, [this, room] { place(room); });
}

void ClusterNode::place(const std::string& room) {
  if (owned_.count(room) || bridged_.count(room)) return;
  if (!up_) {
    // Redis away: rooms wait a moment for it (a node just started is
    // still connecting), then this node owns them itself.
    unplaced_.insert(room);
    if (Clock::now() - waiting_since_ >= kOwnWithoutRedisAfter) own_unplaced();
    return;
  }
  commands_->command({"GET", keys::room_owner(room)}, [this, room](const RedisReply* owner) {
    if (!owner) return own_locally(room);
    if (owner->type == RedisReply::Type::string) return owner->text == node_ ? acquire(room) : bridge(room);
    const std::string target = least_loaded();
    // Counted at once, so that rooms opened together before the next load
    // report spread out instead of all going to the same node.
    loads_[target] += kRoomPlacementLoad;
    if (target == node_) return acquire(room);
    spdlog::info("cluster: room {} placed on node {}, the least loaded", room, target);
    bridge(room);
    commands_->command({"PUBLISH", keys::node_inbox(target), "own " + room});
  });
}

void ClusterNode::acquire(const std::string& room) {
  if (owned_.count(room) || acquiring_.count(room) || !up_) return;
  acquiring_.insert(room);
  commands_->command({"SET", keys::room_owner(room), node_, "NX", "PX", std::to_string(kLeaseMs)},
                     [this, room](const RedisReply* taken) {
                       if (!taken || !taken->is_status("OK") || !commands_) {
                         acquiring_.erase(room);
                         if (taken && services_.rooms.find(room)) bridge(room);  // another node was first
                         return;
                       }
                       commands_->command({"HGETALL", keys::room_members(room)}, [this, room](const RedisReply* members) {
                         if (!commands_) return (void)acquiring_.erase(room);
                         const RedisReply no_members;
                         commands_->command({"GET", keys::room_state(room)},
                                            [this, room, members = members ? *members : no_members](const RedisReply* state) {
                                              restore(room, members, state ? *state : RedisReply{});
                                            });
                       });
                     });
}

void ClusterNode::restore(const std::string& name, const RedisReply& members, const RedisReply& state) {
  acquiring_.erase(name);
  const bool lobby = name == "lobby" && services_.config.demo_room;
  auto room = services_.rooms.find_or_create(name, lobby, /*place=*/false);
  if (!room) return;
  owned_.insert(name);
  if (bridged_.erase(name) && subscriber_) subscriber_->unsubscribe({keys::room_down(name)});
  if (subscriber_) subscriber_->subscribe({keys::room_up(name)});
  commands_->command({"SADD", keys::kRooms, name});
  // The record is read from Redis: checked as the news is (cluster_message_check.hpp).
  std::vector<bridge::MemberRecord> records;
  for (std::size_t i = 0; i + 1 < members.elements.size(); i += 2) {
    const std::string& bytes = members.elements[i + 1].text;
    auto record = bridge::decode_member(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const auto why = record ? cluster_check::refusal_of(*record) : std::optional<std::string>("unreadable");
    if (why) refuse(record ? record->node : "unknown", "room " + name + ": a member's record: " + *why);
    else records.push_back(std::move(*record));
  }
  std::optional<bridge::RoomState> moods;
  if (state.type == RedisReply::Type::string)
    moods = bridge::decode_state(reinterpret_cast<const std::uint8_t*>(state.text.data()), state.text.size());
  if (moods)
    if (const auto why = cluster_check::refusal_of(*moods)) {
      refuse("unknown", "room " + name + ": its moods: " + *why);
      moods.reset();
    }
  const bool fresh = records.empty();
  spdlog::info("cluster: node {} owns room {} now ({} members restored)", node_, name, records.size());
  room->take_over(std::move(records), std::move(moods), live_);
  if (lobby && fresh) seat_lobby_residents(services_.lobby_faces, room);
}

void ClusterNode::own_unplaced() {
  for (const auto& room : std::exchange(unplaced_, {})) own_locally(room);
}

void ClusterNode::own_locally(const std::string& name) {
  auto room = services_.rooms.find(name);
  if (!room || owned_.count(name)) return;
  owned_.insert(name);
  spdlog::warn("cluster: Redis is away; room {} is owned here for now", name);
  room->take_over({}, std::nullopt, {});
  if (name == "lobby" && services_.config.demo_room) seat_lobby_residents(services_.lobby_faces, room);
}

void ClusterNode::bridge(const std::string& room) {
  if (owned_.count(room) || !bridged_.insert(room).second) return;
  if (subscriber_ && up_) subscriber_->subscribe({keys::room_down(room)});
}

void ClusterNode::on_message(std::string_view channel_view, std::string_view payload) {
  const std::string channel(channel_view);
  const auto* data = reinterpret_cast<const std::uint8_t*>(payload.data());
  if (channel == keys::kLimitsChannel) return on_limits(payload);
  if (channel == keys::kAvatarDeletions) return forget_deleted_avatar(payload);
  if (channel == keys::node_inbox(node_)) {
    if (payload.rfind("own ", 0) == 0) {
      const std::string room(payload.substr(4));
      if (is_valid_room_name(room)) acquire(room);
    }
    return;
  }
  const auto target = keys::parse_room_channel(channel);
  if (target.room.empty()) return;
  if (!services_.rooms.find(target.room)) return;
  if (target.down) {
    auto message = bridge::decode_down(data, payload.size());
    if (!message) return refuse("unknown", "room " + target.room + ": a down message this build cannot read");
    on_down(target.room, std::move(*message));
  } else {
    auto message = bridge::decode_up(data, payload.size());
    if (!message) return refuse("unknown", "room " + target.room + ": an up message this build cannot read");
    on_up(target.room, std::move(*message));
  }
}

void ClusterNode::publish(const std::string& channel, bridge::Bytes message) {
  net::post(strand_, [this, channel, message = std::move(message)] {
    if (up_ && commands_) commands_->command({"PUBLISH", channel, text(message)});
  });
}

void ClusterNode::send_down(const std::string& room, bridge::Bytes message) {
  // Faces are dropped, not queued, while Redis is behind: the next tick has newer ones.
  const bool faces = message.size() > 1 && message[1] == static_cast<std::uint8_t>(bridge::DownKind::tick);
  net::post(strand_, [this, room, faces, message = std::move(message)] {
    if (!up_ || !commands_) return;
    if (faces && commands_->pending_output() > kMaxWaitingOutput) return;
    commands_->command({"PUBLISH", keys::room_down(room), text(message)});
  });
}

void ClusterNode::send_up(const std::string& room, bridge::Bytes message) { publish(keys::room_up(room), std::move(message)); }

void ClusterNode::keep_member(const std::string& room, const bridge::MemberRecord& member) {
  net::post(strand_, [this, room, id = member.info.id, record = bridge::encode(member)] {
    if (up_ && commands_) commands_->command({"HSET", keys::room_members(room), std::to_string(id), text(record)});
  });
}

void ClusterNode::forget_member(const std::string& room, std::uint32_t avatar) {
  net::post(strand_, [this, room, avatar] {
    if (up_ && commands_) commands_->command({"HDEL", keys::room_members(room), std::to_string(avatar)});
  });
}

void ClusterNode::keep_state(const std::string& room, bridge::Bytes state) {
  net::post(strand_, [this, room, state = std::move(state)] {
    if (up_ && commands_) commands_->command({"SET", keys::room_state(room), text(state)});
  });
}

void ClusterNode::keep_chat(const std::string& room, bridge::Bytes chat_message) {
  net::post(strand_, [this, room, line = std::move(chat_message)] {
    if (!up_ || !commands_) return;
    commands_->command({"RPUSH", keys::room_chat(room), text(line)});
    commands_->command({"LTRIM", keys::room_chat(room), std::to_string(-kChatTail), "-1"});
  });
}

void ClusterNode::room_closed(const std::string& room) {
  net::post(strand_, [this, room] {
    leases_.erase(room);
    if (bridged_.erase(room)) {
      if (up_ && subscriber_) subscriber_->unsubscribe({keys::room_down(room)});
      return;
    }
    // A node that drains leaves its rooms' records for whoever takes them over.
    if (services_.state.draining.load() || !owned_.erase(room)) return;
    if (!up_ || !commands_) return;
    subscriber_->unsubscribe({keys::room_up(room)});
    commands_->command({"DEL", keys::room_members(room), keys::room_state(room), keys::room_chat(room)});
    commands_->command({"SREM", keys::kRooms, room});
    commands_->command({"EVAL", kReleaseLease, "1", keys::room_owner(room), node_});
  });
}

}  // namespace fw::server
